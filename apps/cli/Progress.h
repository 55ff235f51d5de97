// One progress printer for the commands that run long (bench's sweep, render's frames and
// recordings): on a terminal a status line on stderr rewritten in place; in a log (stderr not
// a terminal) only the lines worth keeping, with no carriage returns.
#pragma once

#include <string>

namespace manylights {

class ProgressLine {
public:
    ProgressLine();
    // Ends a line left on a terminal (also on an error: the one-line message that follows
    // must start on its own line).
    ~ProgressLine() { endLine(); }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // On a terminal: `text` as the status line, replacing the one before. In a log: nothing.
    void show(const std::string& text);
    // In a log: `text` as a line of its own. On a terminal: nothing.
    void log(const std::string& text);
    // Both: a result a log keeps and a terminal shows until the next status.
    void showAndLog(const std::string& text)
    {
        show(text);
        log(text);
    }
    // On a terminal: the status line erased, or kept with the cursor on the next line.
    void erase();
    void endLine();

private:
    bool terminal_;
    bool pending_ = false;  // a status line is on the terminal, the cursor at its end
};

}  // namespace manylights
