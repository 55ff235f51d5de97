// How long each key was held in each frame (issues 43 and 48, docs/viewer.md "Controls"), so
// that a camera move is the time its key was down, not the time the frame before took: on a
// slow machine a tap then moved the camera by a whole slow frame's worth (10-30 degrees). The
// times are those at which the viewer read the events, between the renderer's passes and
// during its waits for the GPU, not only once a frame. Kept apart from the window so that it
// is tested without one.
#pragma once

#include <map>
#include <optional>
#include <vector>

namespace manylights {

// A press and release within one frame count as at least this long, as a script's `key` does:
// both may be read at once (stamped with one time) where a pass holds the main thread.
inline constexpr double kTapSeconds = 1.0 / 30.0;

struct HeldKey {
    int key;
    double seconds;  // how long it was held in the frame
};

class HeldKeys {
public:
    // The moments the window reported the key going down and up (seconds, one clock).
    void press(int key, double time);
    void release(int key, double time);
    // Ends the frame at `now`: each key held at some time since the previous frame ended, with
    // the seconds it was held within the frame; a key first reported since then counts from its
    // press, also where that came before the previous frame's end (its report came late). A
    // key pressed and released since then counts as at least kTapSeconds. Keys released are
    // then forgotten.
    std::vector<HeldKey> endFrame(double now);

private:
    struct Hold {
        double pressed;
        std::optional<double> released;
        bool counted = false;  // by an earlier frame, up to its end
    };
    std::map<int, Hold> holds_;
    std::optional<double> frameStart_;
};

}  // namespace manylights
