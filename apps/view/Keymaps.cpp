#include "apps/view/Keymaps.h"

#include <algorithm>
#include <array>

#include <epoxy/gl.h>  // before GLFW's header, which would include the system's GL/gl.h
#include <GLFW/glfw3.h>

namespace manylights {

namespace {

// The maps' own bindings, as docs/viewer.md tables them.
const std::vector<KeyBinding> kDefaultBindings{
    {KeyAction::OrbitLeft, {GLFW_KEY_LEFT}},
    {KeyAction::OrbitRight, {GLFW_KEY_RIGHT}},
    {KeyAction::OrbitUp, {GLFW_KEY_UP}},
    {KeyAction::OrbitDown, {GLFW_KEY_DOWN}},
    {KeyAction::DollyIn, {GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD}},
    {KeyAction::DollyOut, {GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT}},
    {KeyAction::FlyForward, {GLFW_KEY_W}},
    {KeyAction::FlyLeft, {GLFW_KEY_A}},
    {KeyAction::FlyBack, {GLFW_KEY_S}},
    {KeyAction::FlyRight, {GLFW_KEY_D}},
    {KeyAction::ToggleAxes, {GLFW_KEY_X}},
    {KeyAction::ToggleWireframe, {GLFW_KEY_L}},
    {KeyAction::ForwardOrDeferred, {GLFW_KEY_M}},
    {KeyAction::NextTechnique, {GLFW_KEY_T}},
    {KeyAction::NextView, {GLFW_KEY_V}},
    {KeyAction::TogglePause, {GLFW_KEY_P, GLFW_KEY_SPACE}},
    {KeyAction::Screenshot, {GLFW_KEY_F12, GLFW_KEY_PRINT_SCREEN}},
    {KeyAction::PrintCamera, {GLFW_KEY_C}},
    {KeyAction::TogglePanel, {GLFW_KEY_F1}},
    {KeyAction::Quit, {GLFW_KEY_ESCAPE, GLFW_KEY_Q}},
};

// The deferred-rendering course project's keys: 'a' axes, 'd' deferred, 't' textured forward,
// 'w' wireframe, '+'/'-' towards and away from the look-at point and the arrows rotating the
// view about it (held), 'q' quit.
const std::vector<KeyBinding> kDeferredCourseBindings{
    {KeyAction::ToggleAxes, {GLFW_KEY_A}},
    {KeyAction::UseDeferred, {GLFW_KEY_D}},
    {KeyAction::UseTexturedForward, {GLFW_KEY_T}},
    {KeyAction::ToggleWireframe, {GLFW_KEY_W}},
    {KeyAction::DollyIn, {GLFW_KEY_EQUAL, GLFW_KEY_KP_ADD}},
    {KeyAction::DollyOut, {GLFW_KEY_MINUS, GLFW_KEY_KP_SUBTRACT}},
    {KeyAction::OrbitLeft, {GLFW_KEY_LEFT}},
    {KeyAction::OrbitRight, {GLFW_KEY_RIGHT}},
    {KeyAction::OrbitUp, {GLFW_KEY_UP}},
    {KeyAction::OrbitDown, {GLFW_KEY_DOWN}},
    {KeyAction::Quit, {GLFW_KEY_Q}},
};

// The stencil light-volume write-up's keys: 'w'/'s' forward and back, 'a'/'d' up and down, the
// arrows look around (held), 'r' turns the camera about the look-at point until pressed again,
// 'v' the light volumes, 'u' the volumes in their colours without lighting, 'p'/'o'/'i'
// ambient, diffuse, specular, 'c' the volumes' corners only (the volume-corners view: each
// volume's vertices as points over the lit image, where the write-up shows which corners its
// volumes have), 'q' quit.
const std::vector<KeyBinding> kStencilVolumesBindings{
    {KeyAction::FlyForward, {GLFW_KEY_W}},
    {KeyAction::FlyBack, {GLFW_KEY_S}},
    {KeyAction::FlyUp, {GLFW_KEY_A}},
    {KeyAction::FlyDown, {GLFW_KEY_D}},
    {KeyAction::LookLeft, {GLFW_KEY_LEFT}},
    {KeyAction::LookRight, {GLFW_KEY_RIGHT}},
    {KeyAction::LookUp, {GLFW_KEY_UP}},
    {KeyAction::LookDown, {GLFW_KEY_DOWN}},
    {KeyAction::ToggleRotation, {GLFW_KEY_R}},
    {KeyAction::ToggleVolumes, {GLFW_KEY_V}},
    {KeyAction::ToggleUnlitVolumes, {GLFW_KEY_U}},
    {KeyAction::ToggleAmbient, {GLFW_KEY_P}},
    {KeyAction::ToggleDiffuse, {GLFW_KEY_O}},
    {KeyAction::ToggleSpecular, {GLFW_KEY_I}},
    {KeyAction::ToggleVolumeCorners, {GLFW_KEY_C}},
    {KeyAction::Quit, {GLFW_KEY_Q}},
};

bool names(const std::vector<KeyBinding>& bindings, int key)
{
    return std::any_of(bindings.begin(), bindings.end(), [key](const KeyBinding& binding) {
        return std::find(binding.keys.begin(), binding.keys.end(), key) != binding.keys.end();
    });
}

// A seed's own bindings, then the default's keys it does not name: an action both have keeps
// one row, with the seed's keys first.
std::vector<KeyBinding> withDefaultKeys(const std::vector<KeyBinding>& own)
{
    std::vector<KeyBinding> table = own;
    for (const KeyBinding& binding : kDefaultBindings) {
        std::vector<int> keys;
        for (int key : binding.keys)
            if (!names(own, key))
                keys.push_back(key);
        if (keys.empty())
            continue;
        auto row = std::find_if(table.begin(), table.end(),
                                [&binding](const KeyBinding& entry) { return entry.action == binding.action; });
        if (row == table.end())
            table.push_back({binding.action, keys});
        else
            row->keys.insert(row->keys.end(), keys.begin(), keys.end());
    }
    return table;
}

struct ScriptKeyName {
    const char* name;
    int key;
};
constexpr ScriptKeyName kScriptKeys[] = {
    {"left", GLFW_KEY_LEFT},     {"right", GLFW_KEY_RIGHT}, {"up", GLFW_KEY_UP},   {"down", GLFW_KEY_DOWN},
    {"plus", GLFW_KEY_EQUAL},    {"minus", GLFW_KEY_MINUS}, {"w", GLFW_KEY_W},     {"a", GLFW_KEY_A},
    {"s", GLFW_KEY_S},           {"d", GLFW_KEY_D},         {"x", GLFW_KEY_X},     {"l", GLFW_KEY_L},
    {"m", GLFW_KEY_M},           {"t", GLFW_KEY_T},         {"v", GLFW_KEY_V},     {"p", GLFW_KEY_P},
    {"space", GLFW_KEY_SPACE},   {"f1", GLFW_KEY_F1},       {"f12", GLFW_KEY_F12}, {"c", GLFW_KEY_C},
    {"r", GLFW_KEY_R},           {"u", GLFW_KEY_U},         {"o", GLFW_KEY_O},     {"i", GLFW_KEY_I},
    {"escape", GLFW_KEY_ESCAPE}, {"q", GLFW_KEY_Q},
};

}  // namespace

const std::vector<std::string>& keymapNames()
{
    static const std::vector<std::string> names = namesOf(kKeymapNames);
    return names;
}

std::string_view keymapName(Keymap map) { return nameOf(kKeymapNames, map); }

std::optional<Keymap> parseKeymap(std::string_view name) { return parseName(kKeymapNames, name); }

bool isHeldAction(KeyAction action) { return action <= KeyAction::LookDown; }

std::string_view actionDescription(KeyAction action)
{
    switch (action) {
    case KeyAction::OrbitLeft: return "orbit left";
    case KeyAction::OrbitRight: return "orbit right";
    case KeyAction::OrbitUp: return "orbit up";
    case KeyAction::OrbitDown: return "orbit down";
    case KeyAction::DollyIn: return "towards the look-at point";
    case KeyAction::DollyOut: return "away from the look-at point";
    case KeyAction::FlyForward: return "fly forward";
    case KeyAction::FlyBack: return "fly back";
    case KeyAction::FlyLeft: return "fly left";
    case KeyAction::FlyRight: return "fly right";
    case KeyAction::FlyUp: return "fly up";
    case KeyAction::FlyDown: return "fly down";
    case KeyAction::LookLeft: return "look left";
    case KeyAction::LookRight: return "look right";
    case KeyAction::LookUp: return "look up";
    case KeyAction::LookDown: return "look down";
    case KeyAction::ToggleAxes: return "axes";
    case KeyAction::ToggleWireframe: return "wireframe";
    case KeyAction::ForwardOrDeferred: return "forward / deferred";
    case KeyAction::NextTechnique: return "next technique";
    case KeyAction::NextView: return "next view";
    case KeyAction::TogglePause: return "pause / resume";
    case KeyAction::Screenshot: return "screenshot (no panel)";
    case KeyAction::PrintCamera: return "print camera";
    case KeyAction::TogglePanel: return "hide / show the panel";
    case KeyAction::Quit: return "quit";
    case KeyAction::UseDeferred: return "deferred technique";
    case KeyAction::UseTexturedForward: return "textured forward";
    case KeyAction::ToggleRotation: return "rotate about the look-at point";
    case KeyAction::ToggleVolumes: return "light volumes";
    case KeyAction::ToggleUnlitVolumes: return "light volumes, unlit";
    case KeyAction::ToggleAmbient: return "ambient";
    case KeyAction::ToggleDiffuse: return "diffuse";
    case KeyAction::ToggleSpecular: return "specular";
    case KeyAction::ToggleVolumeCorners: return "volume corners";
    }
    return "";
}

const std::vector<KeyBinding>& keyBindings(Keymap map)
{
    static const std::array<std::vector<KeyBinding>, 3> tables{
        kDefaultBindings, withDefaultKeys(kDeferredCourseBindings), withDefaultKeys(kStencilVolumesBindings)};
    return tables[static_cast<std::size_t>(map)];
}

std::optional<KeyAction> actionOfKey(Keymap map, int key)
{
    for (const KeyBinding& binding : keyBindings(map))
        if (std::find(binding.keys.begin(), binding.keys.end(), key) != binding.keys.end())
            return binding.action;
    return std::nullopt;
}

std::string keyName(int key)
{
    switch (key) {
    case GLFW_KEY_LEFT: return "Left";
    case GLFW_KEY_RIGHT: return "Right";
    case GLFW_KEY_UP: return "Up";
    case GLFW_KEY_DOWN: return "Down";
    case GLFW_KEY_EQUAL: return "+";  // '=' unshifted on most layouts
    case GLFW_KEY_KP_ADD: return "keypad +";
    case GLFW_KEY_MINUS: return "-";
    case GLFW_KEY_KP_SUBTRACT: return "keypad -";
    case GLFW_KEY_SPACE: return "Space";
    case GLFW_KEY_ESCAPE: return "Esc";
    case GLFW_KEY_PRINT_SCREEN: return "Print Screen";
    default: break;
    }
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F25)
        return std::string(1, 'F').append(std::to_string(key - GLFW_KEY_F1 + 1));
    if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) || (key >= GLFW_KEY_0 && key <= GLFW_KEY_9))
        return std::string(1, static_cast<char>(key));  // GLFW's codes of these are their ASCII capitals
    return std::string("key ").append(std::to_string(key));
}

std::string keysOf(Keymap map, KeyAction action)
{
    std::string joined;
    for (const KeyBinding& binding : keyBindings(map))
        if (binding.action == action)
            for (int key : binding.keys) {
                if (!joined.empty())
                    joined += ", ";
                joined += keyName(key);
            }
    return joined;
}

std::string keymapListing()
{
    std::string listing;
    for (const std::string& name : keymapNames()) {
        const Keymap map = *parseKeymap(name);
        std::size_t widest = 0;
        for (const KeyBinding& binding : keyBindings(map))
            widest = std::max(widest, keysOf(map, binding.action).size());
        listing.append(name).append(":\n");
        for (const KeyBinding& binding : keyBindings(map)) {
            const std::string keys = keysOf(map, binding.action);
            listing.append("  ").append(keys).append(widest + 2 - keys.size(), ' ');
            listing.append(actionDescription(binding.action));
            listing.append(isHeldAction(binding.action) ? " (held)\n" : "\n");
        }
    }
    return listing;
}

const std::vector<std::string>& scriptKeyNames()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> result;
        for (const ScriptKeyName& entry : kScriptKeys)
            result.emplace_back(entry.name);
        return result;
    }();
    return names;
}

int scriptKey(std::string_view name)
{
    for (const ScriptKeyName& entry : kScriptKeys)
        if (name == entry.name)
            return entry.key;
    return GLFW_KEY_UNKNOWN;
}

}  // namespace manylights
