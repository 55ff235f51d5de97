// The two kinds of error (CODE_STYLE.md, "Errors").
//
// A user's mistake (bad scene file, missing or broken asset, impossible size) is an Error:
// it carries one complete line that names the file and the position, and the CLI prints it
// and exits 1. A programmer's mistake is an assertion (ML_ASSERT), which names the function
// and aborts.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <string_view>

namespace manylights {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& message) : std::runtime_error(message) {}
};

// `text` with its control characters escaped (\n, \t, \r, \xNN), so that a message naming a
// file whose name holds a newline is still one line. Every error message is printed through it.
std::string printableLine(std::string_view text);

[[noreturn]] inline void assertionFailed(const char* expression, const char* function, const char* file, int line)
{
    std::fprintf(stderr, "manylights: internal error: %s failed in %s (%s:%d)\n", expression, function, file, line);
    std::abort();
}

}  // namespace manylights

#define ML_ASSERT(expression)                                                                                          \
    ((expression) ? static_cast<void>(0) : ::manylights::assertionFailed(#expression, __func__, __FILE__, __LINE__))
