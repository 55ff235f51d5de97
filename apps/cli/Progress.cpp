// The progress printer of apps/cli/Progress.h.
#include "apps/cli/Progress.h"

#include <cstdio>
#include <unistd.h>

namespace manylights {

ProgressLine::ProgressLine() : terminal_(::isatty(STDERR_FILENO) != 0) {}

void ProgressLine::show(const std::string& text)
{
    if (!terminal_)
        return;
    // Back to the line's start, the text, then the rest of the old line cleared.
    std::fprintf(stderr, "\r%s\033[K", text.c_str());
    std::fflush(stderr);
    pending_ = true;
}

void ProgressLine::log(const std::string& text)
{
    if (terminal_)
        return;
    std::fprintf(stderr, "%s\n", text.c_str());
    std::fflush(stderr);
}

void ProgressLine::erase()
{
    if (!pending_)
        return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    pending_ = false;
}

void ProgressLine::endLine()
{
    if (!pending_)
        return;
    std::fputc('\n', stderr);
    std::fflush(stderr);
    pending_ = false;
}

}  // namespace manylights
