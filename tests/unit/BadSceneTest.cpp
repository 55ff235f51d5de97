// Bad scene files (docs/scene-format.md): each must fail with a one-line message that starts
// with the exact position (FILE:LINE:COLUMN for syntax, FILE: /json/pointer for everything
// else) and says what is wrong; a table of them, and two whole messages as a user sees them.
#include <algorithm>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "SceneFileTestSupport.h"

namespace manylights {
namespace {

using test::errorOf;
using test::resolved;
struct BadScene {
    const char* name;
    std::string json;
    std::string where;   // the message starts with "scene.json" + where
    std::string phrase;  // and contains this
};

std::ostream& operator<<(std::ostream& out, const BadScene& bad) { return out << bad.name; }

std::string sphereObject(const std::string& extra)
{
    return R"json({ "objects": [ { "mesh": { "primitive": "sphere", "radius": 1 })json" + extra + " } ] }";
}

std::string withLight(const std::string& light) { return R"json({ "lights": [ )json" + light + " ] }"; }

std::string withSet(const std::string& set) { return R"json({ "light_sets": [ )json" + set + " ] }"; }

std::string withMesh(const std::string& mesh) { return R"json({ "objects": [ { "mesh": )json" + mesh + " } ] }"; }

const std::string kPoint = R"json("type": "point", "pos": [0, 0, 0], "intensity": [1, 1, 1])json";
const std::string kSpot =
    R"json("type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "direction": [0, -1, 0], "range": 1)json";
const std::string kSet =
    R"json("count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1])json";

std::string tooManyObjects()
{
    std::string json = R"json({ "objects": [0)json";
    for (int i = 0; i < 1'000'000; ++i)
        json += ",0";
    return json + "] }";
}

const std::vector<BadScene> kBadScenes = {
    // Syntax: positions are 1-based line:column of the offending character.
    {"TrailingComma", R"json({"ambient": [0, 0, 0],})json", ":1:23: ", "unexpected '}'"},
    {"MissingCommaOnLine3", "{\n  \"camera\": {\n    \"eye\": [0, 1 2]\n  }\n}", ":3:18: ", "expected ']'"},
    {"EmptyText", "", ":1:1: ", "unexpected end of input"},
    {"UnterminatedString", "{\n  \"ambient\": \"abc\n}", ":2:18: ", "invalid string"},
    {"InvalidLiteral", "{\"directional\": {\"shadows\": tru }}", ":1:32: ", "invalid literal"},
    {"Comment", "{\n  // a comment\n}", ":2:3: ", "comments are not allowed in JSON"},
    {"BlockComment", "{\"ambient\": /* grey */ [0, 0, 0]}", ":1:13: ", "comments are not allowed in JSON"},
    {"TrailingGarbage", "{}\n{}", ":2:1: ", "expected end of input"},
    {"ColumnsCountCharactersNotBytes", "{\"ambient\": \"\xC3\xBC\",}", ":1:17: ", "unexpected '}'"},
    {"NumberTooLargeForDouble", "{\n  \"ambient\": [1, 1e400, 0]\n}", ":2:18: ", "number out of range: 1e400"},
    {"DuplicateKey", R"json({"materials": {"grey": {"diffuse": [1, 1, 1], "diffuse": [0, 0, 0]}}})json",
     ": /materials/grey/diffuse: ", "duplicate key 'diffuse'"},
    {"DuplicateKeyInArray", R"json({"lights": [{}, {"type": "point", "type": "spot"}]})json",
     ": /lights/1/type: ", "duplicate key 'type'"},

    // Top level.
    {"TopLevelArray", "[]", ": ", "the top level must be a JSON object, got an array"},
    {"TopLevelNumber", "42", ": ", "the top level must be a JSON object, got a number"},
    {"UnknownTopLevelKeyWithSuggestion", R"json({"lightsets": []})json",
     ": /lightsets: ", "unknown key 'lightsets' (did you mean 'light_sets'?)"},
    {"UnknownTopLevelKeyWithoutSuggestion", R"json({"animation": {}})json",
     ": /animation: ", "unknown key 'animation' (expected one of: camera, "},
    {"AttenuationThresholdZero", R"json({"attenuation_threshold": 0})json",
     ": /attenuation_threshold: ", "must be > 0, got 0"},
    {"BackgroundNegative", R"json({"background": [0, 0, -0.5]})json", ": /background/2: ", "must be >= 0, got -0.5"},
    {"AmbientNotAnArray", R"json({"ambient": 0.1})json",
     ": /ambient: ", "expected an array of 3 numbers, got a number"},
    {"AmbientOverflowsFloat", R"json({"ambient": [1e39, 0, 0]})json",
     ": /ambient/0: ", "1e+39 does not fit in a 32-bit float"},
    {"TooManyObjects", tooManyObjects(), ": /objects: ", "too many objects: 1000001 (at most 1000000)"},

    // Camera.
    {"CameraFovTooLarge", R"json({"camera": {"fov_y": 190}})json", ": /camera/fov_y: ", "must be in (0, 180), got 190"},
    {"CameraFovZero", R"json({"camera": {"fov_y": 0}})json", ": /camera/fov_y: ", "must be in (0, 180), got 0"},
    {"CameraNearZero", R"json({"camera": {"near": 0}})json", ": /camera/near: ", "must be > 0"},
    {"CameraFarBeforeNear", R"json({"camera": {"near": 5, "far": 2}})json",
     ": /camera/far: ", "must be greater than near (5), got 2"},
    {"CameraEyeIsLookAt", R"json({"camera": {"eye": [1, 2, 3], "look_at": [1, 2, 3]}})json",
     ": /camera/look_at: ", "look_at must differ from eye"},
    {"CameraUpParallel", R"json({"camera": {"eye": [0, 5, 0], "look_at": [0, 0, 0]}})json",
     ": /camera: ", "up is parallel to the view direction"},
    {"CameraUpParallelGiven", R"json({"camera": {"eye": [0, 0, 0], "look_at": [1, 0, 0], "up": [-2, 0, 0]}})json",
     ": /camera/up: ", "up is parallel"},
    {"CameraViewOverflows", R"json({"camera": {"eye": [3e38, 0, 0], "look_at": [-3e38, 0, 0]}})json",
     ": /camera/look_at: ", "look_at - eye overflows a float"},
    {"CameraUpZero", R"json({"camera": {"up": [0, 0, 0]}})json", ": /camera/up: ", "must be a non-zero vector"},
    {"CameraEyeTooShort", R"json({"camera": {"eye": [0, 1]}})json",
     ": /camera/eye: ", "expected an array of 3 numbers, got an array of 2 elements"},
    {"CameraEyeString", R"json({"camera": {"eye": [0, "1", 2]}})json",
     ": /camera/eye/1: ", "expected a number, got a string"},
    {"CameraTypo", R"json({"camera": {"lookat": [0, 0, 0]}})json",
     ": /camera/lookat: ", "unknown key 'lookat' (did you mean 'look_at'?)"},

    // Directional light.
    {"DirectionalMissingIntensity", R"json({"directional": {"direction": [0, -1, 0]}})json",
     ": /directional: ", "missing required key 'intensity'"},
    {"DirectionalShadowsNotBool",
     R"json({"directional": {"direction": [0, -1, 0], "intensity": [1, 1, 1], "shadows": "yes"}})json",
     ": /directional/shadows: ", "expected true or false, got a string"},
    {"DirectionalZero", R"json({"directional": {"direction": [0, 0, 0], "intensity": [1, 1, 1]}})json",
     ": /directional/direction: ", "must be a non-zero vector"},

    // Shadowed local lights (issue 47): a whole number >= 0 or "all"; casts_shadows a boolean.
    {"ShadowLightsNegative", R"json({"shadow_lights": -1})json",
     ": /shadow_lights: ", "must be in [0, 2147483647], got -1"},
    {"ShadowLightsFraction", R"json({"shadow_lights": 1.5})json", ": /shadow_lights: ", "expected an integer, got 1.5"},
    {"ShadowLightsOtherString", R"json({"shadow_lights": "every"})json",
     ": /shadow_lights: ", "expected a whole number of lights or 'all', got 'every'"},
    {"ShadowLightsBoolean", R"json({"shadow_lights": true})json",
     ": /shadow_lights: ", "expected a whole number of lights or 'all', got a boolean"},
    {"ShadowLightsTooLarge", R"json({"shadow_lights": 3000000000})json",
     ": /shadow_lights: ", "must be in [0, 2147483647], got 3000000000"},
    {"LightCastsShadowsNotBool", withLight("{" + kPoint + R"json(, "range": 1, "casts_shadows": "no"})json"),
     ": /lights/0/casts_shadows: ", "expected true or false, got a string"},
    {"SpotCastsShadowsNotBool", withLight("{" + kSpot + R"json(, "cutoff": 30, "casts_shadows": 0})json"),
     ": /lights/0/casts_shadows: ", "expected true or false, got a number"},
    {"SetCastsShadowsNotBool", withSet("{" + kSet + R"json(, "casts_shadows": null})json"),
     ": /light_sets/0/casts_shadows: ", "expected true or false, got null"},
    {"LightCastShadowsTypo", withLight("{" + kPoint + R"json(, "range": 1, "cast_shadows": false})json"),
     ": /lights/0/cast_shadows: ", "unknown key 'cast_shadows' (did you mean 'casts_shadows'?)"},

    // Ambient occlusion.
    {"SsaoNotObject", R"json({"ssao": true})json", ": /ssao: ", "expected an object"},
    {"SsaoRadiusZero", R"json({"ssao": {"radius": 0}})json", ": /ssao/radius: ", "must be > 0, got 0"},
    {"SsaoStrengthNegative", R"json({"ssao": {"strength": -1}})json", ": /ssao/strength: ", "must be >= 0, got -1"},
    {"SsaoEnabledNotBool", R"json({"ssao": {"enabled": 1}})json",
     ": /ssao/enabled: ", "expected true or false, got a number"},
    {"SsaoTypo", R"json({"ssao": {"radious": 1}})json", ": /ssao/radious: ", "unknown key 'radious'"},

    // Environment (issue 42).
    {"EnvironmentWithoutMap", R"json({"environment": {"intensity": 1}})json",
     ": /environment: ", "missing required key 'map'"},
    {"EnvironmentMapMissing", R"json({"environment": {"map": "maps/missing.hdr"}})json",
     ": /environment/map: ", "file not found: " + resolved("maps/missing.hdr")},
    {"EnvironmentMapNotHdrOrExr", R"json({"environment": {"map": "textures/sky.png"}})json",
     ": /environment/map: ", "must be a .hdr or .exr file or builtin:studio, got 'textures/sky.png'"},
    {"EnvironmentUnknownBuiltin", R"json({"environment": {"map": "builtin:sunset"}})json",
     ": /environment/map: ", "'builtin:sunset'"},
    {"EnvironmentIntensityNegative", R"json({"environment": {"map": "builtin:studio", "intensity": -1}})json",
     ": /environment/intensity: ", "must be >= 0, got -1"},
    {"EnvironmentIntensityOverflows", R"json({"environment": {"map": "builtin:studio", "intensity": 1e39}})json",
     ": /environment/intensity: ", "1e+39 does not fit in a 32-bit float"},
    {"EnvironmentBackgroundNotBool", R"json({"environment": {"map": "builtin:studio", "background": 1}})json",
     ": /environment/background: ", "expected true or false, got a number"},
    {"EnvironmentTypo", R"json({"environment": {"map": "builtin:studio", "rotate": 90}})json",
     ": /environment/rotate: ", "unknown key 'rotate' (did you mean 'rotation'?)"},

    // Lights.
    {"LightsNotArray", R"json({"lights": {}})json", ": /lights: ", "expected an array, got an object"},
    {"LightMissingType", withLight(R"json({"pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1})json"),
     ": /lights/0: ", "missing required key 'type'"},
    {"LightTypeSpotlight", withLight(R"json({"type": "spotlight"})json"),
     ": /lights/0/type: ", "light type must be 'point' or 'spot', got 'spotlight' (did you mean 'spot'?)"},
    {"LightBothFalloffs", withLight("{" + kPoint + R"json(, "range": 1, "attenuation": {"constant": 1}})json"),
     ": /lights/0: ", "has both 'attenuation' and 'range'"},
    {"LightNoFalloff", withLight("{" + kPoint + "}"), ": /lights/0: ", "give exactly one of 'attenuation' or 'range'"},
    {"LightRangeZero", withLight("{" + kPoint + R"json(, "range": 0})json"),
     ": /lights/0/range: ", "must be > 0, got 0"},
    {"LightAttenuationAllZero",
     withLight("{" + kPoint + R"json(, "attenuation": {"constant": 0, "linear": 0, "quadratic": 0}})json"),
     ": /lights/0/attenuation: ", "must not all be zero"},
    {"LightAttenuationNegative", withLight("{" + kPoint + R"json(, "attenuation": {"linear": -0.1}})json"),
     ": /lights/0/attenuation/linear: ", "must be >= 0, got -0.1"},
    {"LightAttenuationTypo", withLight("{" + kPoint + R"json(, "attenuation": {"quadratc": 1}})json"),
     ": /lights/0/attenuation/quadratc: ", "(did you mean 'quadratic'?)"},
    {"LightIntensityNegative",
     withLight(R"json({"type": "point", "pos": [0, 0, 0], "intensity": [1, -1, 1], "range": 1})json"),
     ": /lights/0/intensity/1: ", "must be >= 0, got -1"},
    {"LightPosMissing", withLight(R"json({"type": "point", "intensity": [1, 1, 1], "range": 1})json"),
     ": /lights/0: ", "missing required key 'pos'"},
    {"LightPositionInsteadOfPos", withLight("{" + kPoint + R"json(, "range": 1, "position": [0, 0, 0]})json"),
     ": /lights/0/position: ", "unknown key 'position' (did you mean 'pos'?)"},
    {"LightNameNotString", withLight("{" + kPoint + R"json(, "range": 1, "name": 3})json"),
     ": /lights/0/name: ", "expected a string, got a number"},
    {"SpotCutoffTooLarge",
     withLight("{" + kPoint + R"json(, "range": 1}, {)json" + kPoint + R"json(, "range": 1}, {)json" + kSpot +
               R"json(, "cutoff": 190})json"),
     ": /lights/2/cutoff: ", "must be in (0, 180], got 190"},
    {"SpotCutoffZero", withLight("{" + kSpot + R"json(, "cutoff": 0})json"),
     ": /lights/0/cutoff: ", "must be in (0, 180], got 0"},
    {"SpotCutoffMissing", withLight("{" + kSpot + "}"), ": /lights/0: ", "missing required key 'cutoff'"},
    {"SpotDirectionMissing",
     withLight(R"json({"type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1, "cutoff": 30})json"),
     ": /lights/0: ", "missing required key 'direction'"},
    {"SpotDirectionZero",
     withLight(R"json({"type": "spot", "pos": [0, 0, 0], "intensity": [1, 1, 1], "range": 1, "cutoff": 30,
                       "direction": [0, 0, 0]})json"),
     ": /lights/0/direction: ", "must be a non-zero vector"},
    {"SpotExponentNegative", withLight("{" + kSpot + R"json(, "cutoff": 30, "exponent": -1})json"),
     ": /lights/0/exponent: ", "must be >= 0, got -1"},
    {"PointWithCutoff", withLight("{" + kPoint + R"json(, "range": 1, "cutoff": 30})json"),
     ": /lights/0/cutoff: ", "'cutoff' applies only to spot lights"},

    // Light sets.
    {"SetCountNegative", withSet(R"json({"count": -1})json"),
     ": /light_sets/0/count: ", "must be in [0, 16777216], got -1"},
    {"SetCountFraction", withSet(R"json({"count": 1.5})json"),
     ": /light_sets/0/count: ", "expected an integer, got 1.5"},
    {"SetCountTooLarge", withSet(R"json({"count": 20000000})json"),
     ": /light_sets/0/count: ", "must be in [0, 16777216], got 20000000"},
    {"SetCountString", withSet(R"json({"count": "8"})json"),
     ": /light_sets/0/count: ", "expected an integer, got a string"},
    {"SetCountsAddUpTooHigh",
     R"json({"light_sets": [
         {"count": 10000000, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1]},
         {"count": 10000000, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [0, 1]}]})json",
     ": /light_sets/1/count: ", "counts add up to 20000000, more than 16777216"},
    {"SetSeedNegative", withSet("{" + kSet + R"json(, "seed": -7})json"),
     ": /light_sets/0/seed: ", "must be in [0, 4294967295], got -7"},
    {"SetMinAboveMax",
     withSet(R"json({"count": 4, "min": [0, 3, 0], "max": [1, 2, 1], "range": [1, 2], "intensity": [0, 1]})json"),
     ": /light_sets/0/max/1: ", "must be >= min on every axis, got max.y 2 < min.y 3"},
    {"SetRangeReversed",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [3, 1], "intensity": [0, 1]})json"),
     ": /light_sets/0/range: ", "interval must have lo <= hi, got [3, 1]"},
    {"SetRangeZero",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [0, 1], "intensity": [0, 1]})json"),
     ": /light_sets/0/range/0: ", "must be > 0, got 0"},
    {"SetRangeNumber",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": 2, "intensity": [0, 1]})json"),
     ": /light_sets/0/range: ", "expected an interval [lo, hi] of 2 numbers, got a number"},
    {"SetIntensityNegative",
     withSet(R"json({"count": 4, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [-1, 1]})json"),
     ": /light_sets/0/intensity/0: ", "must be >= 0, got -1"},
    {"SetMissingMin", withSet(R"json({"count": 4})json"), ": /light_sets/0: ", "missing required key 'min'"},
    {"SetRangeReferenceZero", withSet("{" + kSet + R"json(, "range_reference_count": 0})json"),
     ": /light_sets/0/range_reference_count: ", "must be in [1, 16777216], got 0"},
    {"SetRangeReferenceFraction", withSet("{" + kSet + R"json(, "range_reference_count": 2.5})json"),
     ": /light_sets/0/range_reference_count: ", "expected an integer, got 2.5"},
    {"SetRangeReferenceString", withSet("{" + kSet + R"json(, "range_reference_count": "1024"})json"),
     ": /light_sets/0/range_reference_count: ", "expected an integer, got a string"},
    {"SetRangeReferenceTooLarge", withSet("{" + kSet + R"json(, "range_reference_count": 20000000})json"),
     ": /light_sets/0/range_reference_count: ", "must be in [1, 16777216], got 20000000"},
    {"SpotSetCutoffTooLarge", withSet("{" + kSet + R"json(, "type": "spot", "cutoff": [10, 200]})json"),
     ": /light_sets/0/cutoff/1: ", "must be in (0, 180], got 200"},
    {"SpotSetExponentString", withSet("{" + kSet + R"json(, "type": "spot", "exponent": "high"})json"),
     ": /light_sets/0/exponent: ", "expected a number or an interval [lo, hi], got a string"},
    {"PointSetWithExponent", withSet("{" + kSet + R"json(, "exponent": 2})json"),
     ": /light_sets/0/exponent: ", "'exponent' applies only to spot light sets"},
    {"SetTypeArea", withSet("{" + kSet + R"json(, "type": "area"})json"),
     ": /light_sets/0/type: ", "light set type must be 'point' or 'spot', got 'area'"},

    // Materials.
    {"MaterialsArray", R"json({"materials": []})json", ": /materials: ", "expected an object, got an array"},
    {"MaterialShininessBelowOne", R"json({"materials": {"m": {"shininess": 0.5}}})json",
     ": /materials/m/shininess: ", "must be >= 1, got 0.5"},
    {"MaterialTypo", R"json({"materials": {"m": {"difuse": [1, 1, 1]}}})json",
     ": /materials/m/difuse: ", "unknown key 'difuse' (did you mean 'diffuse'?)"},
    {"MaterialEmissiveNegative", R"json({"materials": {"m": {"emissive": [0, -1, 0]}}})json",
     ": /materials/m/emissive/1: ", "must be >= 0"},
    {"MaterialNameNeedsPointerEscape", R"json({"materials": {"a/b~c": {"shininess": 0}}})json",
     ": /materials/a~1b~0c/shininess: ", "must be >= 1"},
    {"TextureMissing", R"json({"materials": {"m": {"diffuse_map": "textures/missing.png"}}})json",
     ": /materials/m/diffuse_map: ", "file not found: " + resolved("textures/missing.png")},
    {"TextureIsDirectory", R"json({"materials": {"m": {"specular_map": "textures"}}})json",
     ": /materials/m/specular_map: ", "not a regular file"},
    {"TextureEmptyPath", R"json({"materials": {"m": {"normal_map": ""}}})json",
     ": /materials/m/normal_map: ", "expected a file path, got an empty string"},
    {"OpacityAboveOne", R"json({"materials": {"m": {"opacity": 1.5}}})json",
     ": /materials/m/opacity: ", "must be in [0, 1], got 1.5"},
    {"OpacityNegative", R"json({"materials": {"m": {"opacity": -0.1}}})json",
     ": /materials/m/opacity: ", "must be in [0, 1], got -0.1"},
    {"NormalScaleNotANumber", R"json({"materials": {"m": {"normal_scale": "2"}}})json",
     ": /materials/m/normal_scale: ", "expected a number, got a string"},

    // Objects and meshes.
    {"ObjectsNotArray", R"json({"objects": {}})json", ": /objects: ", "expected an array, got an object"},
    {"ObjectMissingMesh", R"json({"objects": [{"name": "x"}]})json", ": /objects/0: ", "missing required key 'mesh'"},
    {"ObjectUnknownMaterial",
     R"json({"materials": {"grey": {}},
             "objects": [{"mesh": {"primitive": "sphere", "radius": 1}, "material": "gray"}]})json",
     ": /objects/0/material: ", "unknown material 'gray' (did you mean 'grey'?)"},
    {"ObjectMaterialWithoutMaterials", sphereObject(R"json(, "material": "grey")json"),
     ": /objects/0/material: ", "unknown material 'grey' (the scene's 'materials' defines none)"},
    {"ObjectMaterialNumber", sphereObject(R"json(, "material": 3)json"),
     ": /objects/0/material: ", "expected a material name or a material object, got a number"},
    {"ObjectInlineMaterialBad", sphereObject(R"json(, "material": {"shininess": 0})json"),
     ": /objects/0/material/shininess: ", "must be >= 1, got 0"},
    {"MeshGltfMissing", withMesh(R"json("models/helmet.gltf")json"),
     ": /objects/0/mesh: ", "file not found: " + resolved("models/helmet.gltf")},
    {"MeshGlbMissing", withMesh(R"json("models/helmet.GLB")json"),
     ": /objects/0/mesh: ", "file not found: " + resolved("models/helmet.GLB")},
    // A model from a folder a Debian package installs: the message names the package.
    {"MeshFromMissingPackage", withMesh(R"json("/usr/share/assimp/models/glTF2/NoSuchModel/NoSuchModel.gltf")json"),
     ": /objects/0/mesh: ",
     "file not found: /usr/share/assimp/models/glTF2/NoSuchModel/NoSuchModel.gltf (installed by the Debian package "
     "assimp-testmodels: apt-get install assimp-testmodels, or scripts/setup.sh)"},
    {"MeshPly", withMesh(R"json("models/bunny.ply")json"),
     ": /objects/0/mesh: ", "unsupported mesh file type '.ply' (expected .obj, .gltf or .glb)"},
    {"MeshObjMissing", withMesh(R"json("models/nothere.obj")json"),
     ": /objects/0/mesh: ", "file not found: " + resolved("models/nothere.obj")},
    {"MeshObjBroken", withMesh(R"json("models/broken.obj")json"), ": /objects/0/mesh: ", "broken.obj"},
    {"MeshNumber", withMesh("7"),
     ": /objects/0/mesh: ", "expected a mesh file path or a primitive object, got a number"},
    {"PrimitiveUnknown", withMesh(R"json({"primitive": "sphre", "radius": 1})json"),
     ": /objects/0/mesh/primitive: ", "unknown primitive 'sphre' (did you mean 'sphere'?)"},
    {"PrimitiveMissing", withMesh(R"json({"radius": 1})json"),
     ": /objects/0/mesh: ", "missing required key 'primitive'"},
    {"SphereRadiusZero", withMesh(R"json({"primitive": "sphere", "radius": 0})json"),
     ": /objects/0/mesh/radius: ", "must be > 0, got 0"},
    {"SphereWithSize", withMesh(R"json({"primitive": "sphere", "size": [1, 1, 1]})json"),
     ": /objects/0/mesh/size: ", "unknown key 'size' (expected one of: primitive, radius)"},
    {"PlaneSizeWrongLength", withMesh(R"json({"primitive": "plane", "size": [1]})json"),
     ": /objects/0/mesh/size: ", "expected an array of 2 numbers, got an array of 1 element"},
    {"BoxSizeNegative", withMesh(R"json({"primitive": "box", "size": [1, -1, 1]})json"),
     ": /objects/0/mesh/size/1: ", "must be > 0, got -1"},
    {"TorusMissingTube", withMesh(R"json({"primitive": "torus", "radius": 1})json"),
     ": /objects/0/mesh: ", "missing required key 'tube'"},
    {"ConeHeightNegative", withMesh(R"json({"primitive": "cone", "radius": 1, "height": -2})json"),
     ": /objects/0/mesh/height: ", "must be > 0, got -2"},

    // Transforms.
    {"TransformMatrixAndTranslate",
     sphereObject(R"json(, "transform": {"translate": [1, 0, 0], "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]})json"),
     ": /objects/0/transform: ", "give either 'matrix' or 'translate'/'rotate'/'scale', not both"},
    {"TransformMatrixShort", sphereObject(R"json(, "transform": {"matrix": [1, 0, 0]})json"),
     ": /objects/0/transform/matrix: ", "expected an array of 16 numbers, got an array of 3 elements"},
    {"TransformMatrixRowMajor",
     sphereObject(R"json(, "transform": {"matrix": [1,0,0,5, 0,1,0,6, 0,0,1,7, 0,0,0,1]})json"),
     ": /objects/0/transform/matrix: ", "must be affine"},
    {"TransformMatrixSingular",
     sphereObject(R"json(, "transform": {"matrix": [1,0,0,0, 0,0,0,0, 0,0,1,0, 0,0,0,1]})json"),
     ": /objects/0/transform/matrix: ", "is singular"},
    {"TransformScaleZero", sphereObject(R"json(, "transform": {"scale": 0})json"),
     ": /objects/0/transform/scale: ", "must be non-zero, got 0"},
    {"TransformScaleComponentZero", sphereObject(R"json(, "transform": {"scale": [1, 0, 1]})json"),
     ": /objects/0/transform/scale/1: ", "must be non-zero, got 0"},
    {"TransformScaleString", sphereObject(R"json(, "transform": {"scale": "2"})json"),
     ": /objects/0/transform/scale: ", "expected a number or an array of 3 numbers, got a string"},
    {"TransformRotateShort", sphereObject(R"json(, "transform": {"rotate": [0, 90]})json"),
     ": /objects/0/transform/rotate: ", "expected an array of 3 numbers, got an array of 2 elements"},
    {"TransformTypo", sphereObject(R"json(, "transform": {"rotation": [0, 90, 0]})json"),
     ": /objects/0/transform/rotation: ", "(did you mean 'rotate'?)"},
    {"TransformTranslateHuge", sphereObject(R"json(, "transform": {"translate": [0, 1e300, 0]})json"),
     ": /objects/0/transform/translate/1: ", "number out of range"},
    // Animation (docs/scene-format.md "Animation").
    {"AnimationNotAnObject", sphereObject(R"json(, "animation": "spin")json"),
     ": /objects/0/animation: ", "expected an object, got a string"},
    {"AnimationTwoKinds", sphereObject(R"json(, "animation": {"spin": {}, "sway": {}})json"),
     ": /objects/0/animation: ", "expected exactly one animation kind (one of: spin, sway, bounce), got 2 keys"},
    {"AnimationUnknownKind", sphereObject(R"json(, "animation": {"spinn": {}})json"),
     ": /objects/0/animation/spinn: ", "unknown animation 'spinn' (did you mean 'spin'?)"},
    {"AnimationLightKindOnObject", sphereObject(R"json(, "animation": {"orbit": {}})json"),
     ": /objects/0/animation/orbit: ", "unknown animation 'orbit'"},
    {"AnimationUnknownKey", sphereObject(R"json(, "animation": {"spin": {"sped": 3}})json"),
     ": /objects/0/animation/spin/sped: ", "(did you mean 'speed'?)"},
    {"AnimationSpinSpeedString", sphereObject(R"json(, "animation": {"spin": {"speed": "fast"}})json"),
     ": /objects/0/animation/spin/speed: ", "expected a number, got a string"},
    {"AnimationSpinAxisZero", sphereObject(R"json(, "animation": {"spin": {"axis": [0, 0, 0]}})json"),
     ": /objects/0/animation/spin/axis: ", "must be a non-zero vector"},
    {"AnimationBouncePeriodNegative", sphereObject(R"json(, "animation": {"bounce": {"period": -1}})json"),
     ": /objects/0/animation/bounce/period: ", "must be > 0, got -1"},
    {"AnimationBouncePeriodZero", sphereObject(R"json(, "animation": {"bounce": {"period": 0}})json"),
     ": /objects/0/animation/bounce/period: ", "must be > 0, got 0"},
    {"AnimationBounceSquashOne", sphereObject(R"json(, "animation": {"bounce": {"squash": 1}})json"),
     ": /objects/0/animation/bounce/squash: ", "must be in [0, 1), got 1"},
    {"AnimationBounceHeightNegative", sphereObject(R"json(, "animation": {"bounce": {"height": -2}})json"),
     ": /objects/0/animation/bounce/height: ", "must be >= 0, got -2"},
    {"AnimationSwayVertical", sphereObject(R"json(, "animation": {"sway": {"direction": [0, 1, 0]}})json"),
     ": /objects/0/animation/sway/direction: ", "must be a non-zero horizontal vector"},
    {"AnimationSwayFrequencyNegative", sphereObject(R"json(, "animation": {"sway": {"frequency": -0.5}})json"),
     ": /objects/0/animation/sway/frequency: ", "must be >= 0, got -0.5"},
    {"LightAnimationObjectKind",
     withLight(R"json({"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 2,
                       "animation": {"bounce": {}}})json"),
     ": /lights/0/animation/bounce: ", "unknown animation 'bounce' (expected one of: orbit, drift)"},
    {"LightOrbitRadiusNegative",
     withLight(R"json({"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 2,
                       "animation": {"orbit": {"radius": -1}}})json"),
     ": /lights/0/animation/orbit/radius: ", "must be >= 0, got -1"},
    {"LightDriftPeriodZero", withLight(R"json({"type": "point", "pos": [0, 1, 0], "intensity": [1, 1, 1], "range": 2,
                       "animation": {"drift": {"period": [1, 0, 1]}}})json"),
     ": /lights/0/animation/drift/period/1: ", "must be > 0, got 0"},
    {"SetAnimationTypo",
     withSet(R"json({"count": 2, "min": [0, 0, 0], "max": [1, 1, 1], "range": [1, 2], "intensity": [1, 1],
                     "animation": {"orbit": {"phse": 3}}})json"),
     ": /light_sets/0/animation/orbit/phse: ", "(did you mean 'phase'?)"},
    {"LightMarkersRadiusZero", R"json({"light_markers": {"radius": 0}})json",
     ": /light_markers/radius: ", "must be > 0, got 0"},
    {"LightMarkersNoRadius", R"json({"light_markers": {}})json", ": /light_markers: ", "missing required key 'radius'"},
    {"RevolutionAmplitudeTooLarge", withMesh(R"json({"primitive": "revolution", "radius": 0.5, "amplitude": 0.5})json"),
     ": /objects/0/mesh/amplitude: ", "must be less than radius (0.5)"},
    {"RevolutionDynamicWithTime", withMesh(R"json({"primitive": "revolution", "dynamic": true, "time": 1})json"),
     ": /objects/0/mesh/time: ", "applies only to a static surface"},
};

class BadSceneTest : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneTest, ErrorNamesThePosition)
{
    const BadScene& bad = GetParam();
    const std::string message = errorOf(bad.json);
    const std::string prefix = "scene.json" + bad.where;
    EXPECT_EQ(message.substr(0, prefix.size()), prefix) << message;
    EXPECT_NE(message.find(bad.phrase), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(SceneLoader, BadSceneTest, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& param) { return std::string(param.param.name); });

TEST(SceneLoader, BadSceneTableIsLargeAndNamesAreUnique)
{
    EXPECT_GE(kBadScenes.size(), 40u);
    std::vector<std::string> names;
    for (const BadScene& bad : kBadScenes)
        names.emplace_back(bad.name);
    std::sort(names.begin(), names.end());
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

// Two whole messages, exactly, as a user sees them.
TEST(SceneLoader, ExactMessages)
{
    EXPECT_EQ(errorOf("{\n  \"lights\": [\n    { \"type\": \"point\", }\n  ]\n}"),
              "scene.json:3:24: syntax error while parsing object key: unexpected '}'; expected string literal");
    EXPECT_EQ(errorOf(R"json({"materials": {"m": {"colour": [1, 0, 0]}}})json"),
              "scene.json: /materials/m/colour: unknown key 'colour' (expected one of: diffuse, specular, shininess, "
              "emissive, diffuse_map, specular_map, normal_map, normal_scale, opacity, opacity_map, base_color, "
              "metallic, roughness, base_color_map, metallic_roughness_map, occlusion_map)");
}

}  // namespace
}  // namespace manylights
