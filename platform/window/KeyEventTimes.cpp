#include "platform/window/KeyEventTimes.h"

#include <algorithm>

#include <poll.h>

#include <epoxy/gl.h>
#include <GLFW/glfw3.h>
// Xlib last: its macros (None, True, KeyPress, ...) would clash with the headers above.
#include <X11/XKBlib.h>
#include <X11/Xlib.h>

// GLFW's own accessor for a window's X11 id (<GLFW/glfw3native.h>, which declares it, also
// includes the XRandR headers, which this project does not otherwise need).
extern "C" Window glfwGetX11Window(GLFWwindow* window);

namespace manylights {

namespace {
// How often the thread, waiting for X events, checks whether it is asked to stop.
constexpr int kStopCheckMs = 50;
}  // namespace

void KeyEventLog::note(int scancode, bool press, double time)
{
    notes_.push_back({scancode, press, time});
    while (!notes_.empty() && notes_.front().time < time - kKeepSeconds)
        notes_.pop_front();
}

std::optional<double> KeyEventLog::take(int scancode, bool press, double readAt)
{
    // Notes from before the key's last reported event are copies GLFW's report came ahead of:
    // they belong to events already timed.
    const auto last = lastEventTimes_.find(scancode);
    const double after = last == lastEventTimes_.end() ? -1.0 : last->second;
    const auto matches = [&](const Note& note) {
        return note.scancode == scancode && note.press == press && note.time > after && note.time <= readAt;
    };
    std::deque<Note>::iterator found = notes_.end();
    if (press) {
        found = std::find_if(notes_.begin(), notes_.end(), matches);
    } else {
        const auto reversed = std::find_if(notes_.rbegin(), notes_.rend(), matches);
        if (reversed != notes_.rend())
            found = std::prev(reversed.base());
    }
    const std::optional<double> time = found == notes_.end() ? std::nullopt : std::optional(found->time);
    const double through = time.value_or(readAt);
    notes_.erase(std::remove_if(notes_.begin(), notes_.end(),
                                [&](const Note& note) { return note.scancode == scancode && note.time <= through; }),
                 notes_.end());
    lastEventTimes_[scancode] = through;
    return time;
}

KeyEventTimes::KeyEventTimes(GLFWwindow* window)
{
    Display* display = XOpenDisplay(nullptr);
    if (!display)
        return;
    const Window id = glfwGetX11Window(window);
    if (id == None) {
        XCloseDisplay(display);
        return;
    }
    // The server's auto-repeat as repeated presses and one release, as GLFW asks for its own
    // connection: a held key's release is then its last.
    XkbSetDetectableAutoRepeat(display, True, nullptr);
    XSelectInput(display, id, KeyPressMask | KeyReleaseMask);
    XSync(display, False);
    // The connection is the thread's alone from here on.
    thread_ = std::thread([this, display] { run(display); });
}

KeyEventTimes::~KeyEventTimes()
{
    stop_ = true;
    if (thread_.joinable())
        thread_.join();
}

std::optional<double> KeyEventTimes::take(int scancode, bool press, double readAt)
{
    const std::lock_guard lock(mutex_);
    return log_.take(scancode, press, readAt);
}

void KeyEventTimes::run(void* connection)
{
    auto* display = static_cast<Display*>(connection);
    const int socket = ConnectionNumber(display);
    while (!stop_) {
        pollfd waiting{socket, POLLIN, 0};
        poll(&waiting, 1, kStopCheckMs);
        while (XPending(display) > 0) {
            XEvent event;
            XNextEvent(display, &event);
            if (event.type != KeyPress && event.type != KeyRelease)
                continue;
            const double time = glfwGetTime();
            const std::lock_guard lock(mutex_);
            log_.note(static_cast<int>(event.xkey.keycode), event.type == KeyPress, time);
        }
    }
    XCloseDisplay(display);
}

}  // namespace manylights
