// Shader files with `#include "file"` and injected `#define`s.
//
// GLSL has no include and its #line names source strings by number, not by file. The
// resolver numbers every file it pulls in, emits `#line LINE NUMBER` around each include,
// and mapCompileLog() turns the driver's "NUMBER:LINE" or "NUMBER(LINE)" prefixes back into
// "file:LINE", so a compile error names the real file and line.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace manylights::gl {

// Reads a shader file by its path under shaders/ (e.g. "lib/lighting.glsl").
using ShaderFileReader = std::function<std::optional<std::string>(const std::string& name)>;

// Reads the shaders compiled into the binary.
ShaderFileReader embeddedShaderReader();
// Reads shaders from a directory on disk (the viewer uses it to reload edited shaders).
ShaderFileReader directoryShaderReader(std::string directory);

// The reader Programs use when given none: the embedded shaders unless the process replaced it
// (the viewer's --shader-dir, so that its techniques compile the files being edited).
const ShaderFileReader& defaultShaderReader();
void setDefaultShaderReader(ShaderFileReader reader);

using Defines = std::vector<std::pair<std::string, std::string>>;

struct ResolvedShader {
    std::string text;
    std::vector<std::string> files;  // source-string number -> file name
};

// Throws manylights::Error naming the including file and line when an include is missing.
ResolvedShader resolveShader(const std::string& name, const Defines& defines, const ShaderFileReader& reader);

// Rewrites a driver's info log so that positions name files instead of source numbers.
std::string mapCompileLog(const std::string& log, const std::vector<std::string>& files);

}  // namespace manylights::gl
