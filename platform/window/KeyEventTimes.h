// When the display server delivered each key press and release (issue 48, docs/viewer.md
// "Controls"), known to within 10 ms however long the viewer's frames and passes take
// (measured: scripts/measure-held-keys.sh).
//
// GLFW reads a window's events on the main thread only, which is the one that renders: it
// learns of a key when it next polls, which on llvmpipe can be 60-120 ms of vertex work in the
// geometry pass later, or a second of counting in the light-count view. So a thread of its own opens a
// second connection to the X server and asks for the same window's key events: the server sends
// every client that asks a copy of each, at once, and the thread notes when its copy came. The
// window's events are still GLFW's, read on the main thread; when GLFW reports a press or a
// release, take() gives the time the copy came. Without X11 (or where the connection cannot be
// opened) nothing is noted, and the viewer uses the time GLFW reported the event.
#pragma once

#include <atomic>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

struct GLFWwindow;

namespace manylights {

// The key events noted, and which of them a press or release GLFW reports was (no X11 here,
// so that it is tested alone). Times are glfwGetTime's.
class KeyEventLog {
public:
    // Notes are kept this long at most: a note no report claims (a key typed into another
    // window's copy) is dropped then.
    static constexpr double kKeepSeconds = 10.0;

    void note(int scancode, bool press, double time);
    // For GLFW's report, read at `readAt`, of a press (the first noted press of the key, the
    // ones after it being the server's auto-repeat) or a release (the last noted release of the
    // key) no later than `readAt`: the time it was noted, and every note of that key up to it
    // forgotten. nullopt where none is noted (the copy has not come yet: `readAt` is then as
    // good).
    std::optional<double> take(int scancode, bool press, double readAt);

private:
    struct Note {
        int scancode;
        bool press;
        double time;
    };
    std::deque<Note> notes_;                // oldest first
    std::map<int, double> lastEventTimes_;  // each key's last event taken, by its time
};

class KeyEventTimes {
public:
    // Starts the thread for `window`'s key events where GLFW runs on X11 and a second connection
    // to its display opens; otherwise notes nothing.
    explicit KeyEventTimes(GLFWwindow* window);
    ~KeyEventTimes();
    KeyEventTimes(const KeyEventTimes&) = delete;
    KeyEventTimes& operator=(const KeyEventTimes&) = delete;

    // Whether a thread notes key events (X11).
    bool isNoting() const { return thread_.joinable(); }
    // As KeyEventLog::take, for GLFW's report of a key event with its scancode.
    std::optional<double> take(int scancode, bool press, double readAt);

private:
    // Notes the key events of `display` (an Xlib Display, its window's events selected) until
    // asked to stop, then closes it.
    void run(void* display);

    std::mutex mutex_;
    KeyEventLog log_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace manylights
