#include "apps/view/HeldKeys.h"

#include <algorithm>

namespace manylights {

void HeldKeys::press(int key, double time)
{
    // A repeated press (no release seen between) keeps the first.
    auto [it, added] = holds_.try_emplace(key, Hold{time, std::nullopt});
    if (!added && it->second.released)
        it->second = Hold{time, std::nullopt};
}

void HeldKeys::release(int key, double time)
{
    if (auto it = holds_.find(key); it != holds_.end() && !it->second.released)
        it->second.released = time;
}

std::vector<HeldKey> HeldKeys::endFrame(double now)
{
    std::vector<HeldKey> held;
    for (auto it = holds_.begin(); it != holds_.end();) {
        Hold& hold = it->second;
        const double from = hold.counted ? std::max(hold.pressed, frameStart_.value_or(hold.pressed)) : hold.pressed;
        const double to = std::min(hold.released.value_or(now), now);
        double seconds = std::max(0.0, to - from);
        if (hold.released && !hold.counted)  // a tap
            seconds = std::max(seconds, kTapSeconds);
        if (seconds > 0.0)
            held.push_back({it->first, seconds});
        hold.counted = true;
        it = hold.released ? holds_.erase(it) : std::next(it);
    }
    frameStart_ = now;
    return held;
}

}  // namespace manylights
