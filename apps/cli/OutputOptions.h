// Which of render's options apply to which output format (docs/cli.md "Options and outputs"):
// one table, which the command line's check reads and a test goes through whole
// (tests/image/CliTest.cpp), so that every option that cannot apply to the output is the same
// usage error (exit 2). Before it, --no-legend with a .pfm output was accepted silently while
// --exposure with one was an error (issue 43).
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "apps/cli/CommandSupport.h"

namespace manylights {

struct OutputOption {
    std::string_view name;             // as the command line spells it
    std::vector<ImageFormat> formats;  // the outputs it applies to
    std::string_view reason;           // why it applies to no other output
};

// Every option of `render` that applies to some outputs only.
const std::vector<OutputOption>& outputOptions();

// ".png".
std::string_view formatExtension(ImageFormat format);

// The usage message for the first option of outputOptions() that `given` says is on the command
// line and does not apply to an output of `format`: "--no-legend applies to .png outputs, not
// .pfm: ..."; empty when every given option applies.
std::string outputOptionProblem(const std::function<bool(std::string_view option)>& given, ImageFormat format);

}  // namespace manylights
