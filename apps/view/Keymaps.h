// The viewer's key maps (docs/viewer.md "Controls"): for each map one table of actions and the
// keys that do them, which the key handler (ViewerKeys.cpp), the panel (ViewerPanel.cpp) and
// `view --keymap list` all read, so that what the panel says a key does is what it does
// (issue 43). Keys are GLFW key codes; the tables are tested without a window.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/EnumNames.h"

namespace manylights {

// Which keys do what: the viewer's own, or those of one of the seeds the viewer grew from (the
// deferred-rendering course project, the stencil light-volume write-up), so that their users'
// hands need not relearn.
enum class Keymap { Default, DeferredCourse, StencilVolumes };
inline constexpr EnumNames<Keymap, 3> kKeymapNames{{
    {Keymap::Default, "default"},
    {Keymap::DeferredCourse, "deferred-course"},
    {Keymap::StencilVolumes, "stencil-volumes"},
}};
const std::vector<std::string>& keymapNames();  // "default", "deferred-course", "stencil-volumes"
std::string_view keymapName(Keymap map);
std::optional<Keymap> parseKeymap(std::string_view name);

// What a key does. The camera moves act for as long as their key is held (isHeldAction); the
// others act once per press.
enum class KeyAction {
    OrbitLeft,
    OrbitRight,
    OrbitUp,
    OrbitDown,
    DollyIn,
    DollyOut,
    FlyForward,
    FlyBack,
    FlyLeft,
    FlyRight,
    FlyUp,
    FlyDown,
    LookLeft,
    LookRight,
    LookUp,
    LookDown,
    ToggleAxes,
    ToggleWireframe,
    ForwardOrDeferred,
    NextTechnique,
    NextView,
    TogglePause,
    Screenshot,
    PrintCamera,
    TogglePanel,
    Quit,
    UseDeferred,
    UseTexturedForward,
    ToggleRotation,
    ToggleVolumes,
    ToggleUnlitVolumes,
    ToggleAmbient,
    ToggleDiffuse,
    ToggleSpecular,
    ToggleVolumeCorners,
};

bool isHeldAction(KeyAction action);
// A few words for the panel and the listing (ASCII: the panel's font has no arrows).
std::string_view actionDescription(KeyAction action);

struct KeyBinding {
    KeyAction action;
    std::vector<int> keys;  // GLFW key codes
};

// The map's whole table: its own bindings, then the default map's bindings of the keys it does
// not name (docs/viewer.md: such keys keep their default meaning). No key appears twice.
const std::vector<KeyBinding>& keyBindings(Keymap map);

// The action of `key` in `map`; nullopt for a key the map leaves unbound.
std::optional<KeyAction> actionOfKey(Keymap map, int key);

// How the panel and the listing name a key: "Left", "+", "keypad +", "Space", "F12", "W".
std::string keyName(int key);

// The names of the keys that do `action` in `map`, joined ("P, Space"); empty when none does.
std::string keysOf(Keymap map, KeyAction action);

// `view --keymap list`: every map, each with its table, one binding a line.
std::string keymapListing();

// The keys a script may press (`key NAME`, docs/viewer.md "Scripts"), by name: left right up
// down plus minus w a s d x l m t v p space f1 f12 c r u o i escape q.
const std::vector<std::string>& scriptKeyNames();
// The GLFW key code of a name of scriptKeyNames(); GLFW_KEY_UNKNOWN for any other name.
int scriptKey(std::string_view name);

}  // namespace manylights
