#include "gl/ShaderSource.h"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

#include "core/EmbeddedFiles.h"
#include "core/Error.h"

namespace manylights::gl {

ShaderFileReader embeddedShaderReader()
{
    return [](const std::string& name) -> std::optional<std::string> {
        if (auto text = embeddedFile(name))
            return std::string(*text);
        return std::nullopt;
    };
}

ShaderFileReader directoryShaderReader(std::string directory)
{
    return [directory = std::move(directory)](const std::string& name) -> std::optional<std::string> {
        std::ifstream file(directory + "/" + name, std::ios::binary);
        if (!file)
            return std::nullopt;
        std::ostringstream text;
        text << file.rdbuf();
        return text.str();
    };
}

namespace {
ShaderFileReader& defaultReaderSlot()
{
    static ShaderFileReader reader = embeddedShaderReader();
    return reader;
}
}  // namespace

const ShaderFileReader& defaultShaderReader() { return defaultReaderSlot(); }

void setDefaultShaderReader(ShaderFileReader reader) { defaultReaderSlot() = std::move(reader); }

namespace {

class Resolver {
public:
    explicit Resolver(const ShaderFileReader& reader) : reader_(reader) {}

    ResolvedShader run(const std::string& name, const Defines& defines)
    {
        std::optional<std::string> text = reader_(name);
        if (!text)
            throw Error("shader '" + name + "' not found");
        result_.files.push_back(name);
        included_.insert(name);
        std::istringstream lines(*text);
        std::string line;
        int lineNumber = 0;
        // The #version line must come first; the defines follow it, then a #line restores
        // the numbering of the file.
        while (std::getline(lines, line)) {
            ++lineNumber;
            result_.text += line + "\n";
            if (line.rfind("#version", 0) == 0)
                break;
        }
        for (const auto& [macro, value] : defines)
            result_.text += "#define " + macro + " " + value + "\n";
        result_.text += "#line " + std::to_string(lineNumber + 1) + " 0\n";
        appendBody(lines, name, 0, lineNumber);
        return std::move(result_);
    }

private:
    void appendBody(std::istream& lines, const std::string& name, int fileNumber, int lineNumber)
    {
        static const std::regex includePattern(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
        std::string line;
        while (std::getline(lines, line)) {
            ++lineNumber;
            // Only a line whose first non-blank character is '#' can be an include: std::regex on
            // every line of every program's sources was a measurable share of a small render
            // (docs/testing.md, "The suite's time").
            const std::size_t first = line.find_first_not_of(" \t\r\f\v");
            std::smatch match;
            if (first == std::string::npos || line[first] != '#' || !std::regex_match(line, match, includePattern)) {
                result_.text.append(line).push_back('\n');
                continue;
            }
            const std::string includeName = match[1];
            if (included_.insert(includeName).second) {
                std::optional<std::string> text = reader_(includeName);
                if (!text)
                    throw Error(name + ":" + std::to_string(lineNumber) + ": included shader '" + includeName +
                                "' not found");
                const int includeNumber = static_cast<int>(result_.files.size());
                result_.files.push_back(includeName);
                result_.text += "#line 1 " + std::to_string(includeNumber) + "\n";
                std::istringstream includeLines(*text);
                appendBody(includeLines, includeName, includeNumber, 0);
            }
            result_.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(fileNumber) + "\n";
        }
    }

    const ShaderFileReader& reader_;
    ResolvedShader result_;
    std::set<std::string> included_;  // each file is pulled in once, like #pragma once
};

}  // namespace

ResolvedShader resolveShader(const std::string& name, const Defines& defines, const ShaderFileReader& reader)
{
    return Resolver(reader).run(name, defines);
}

std::string mapCompileLog(const std::string& log, const std::vector<std::string>& files)
{
    // Mesa writes "0:12(7): error: ...", NVIDIA "0(12) : error C1008: ...".
    static const std::regex position(R"(^(\d+)(?::(\d+)\((\d+)\)|\((\d+)\)))");
    std::istringstream lines(log);
    std::string line;
    std::string mapped;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_search(line, match, position)) {
            const std::size_t fileNumber = std::stoul(match[1]);
            const std::string lineNumber = match[2].matched ? match[2].str() : match[4].str();
            const std::string file = fileNumber < files.size() ? files[fileNumber] : match[1].str();
            line = file + ":" + lineNumber + match.suffix().str();
        }
        if (!mapped.empty())
            mapped += "\n";
        mapped += line;
    }
    return mapped;
}

}  // namespace manylights::gl
