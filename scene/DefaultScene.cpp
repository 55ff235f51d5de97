#include "scene/DefaultScene.h"

#include <algorithm>
#include <optional>
#include <variant>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <sstream>
#include <string>

#include "core/EmbeddedFiles.h"
#include "core/Error.h"
#include "scene/Meshes.h"
#include "scene/ObjLoader.h"
#include "scene/Revolution.h"
#include "scene/Transform.h"

namespace manylights {

namespace {

// std::mt19937 is specified to the bit; the std:: distributions are not, so floats are made
// from the top 24 bits by hand to keep the scene identical across standard libraries.
class Random {
public:
    explicit Random(std::uint32_t seed) : engine_(seed) {}

    float unit() { return static_cast<float>(engine_() >> 8) * 0x1p-24f; }  // [0, 1)
    float between(float lo, float hi) { return lo + (hi - lo) * unit(); }
    int below(int n) { return std::min(static_cast<int>(unit() * static_cast<float>(n)), n - 1); }
    bool chance(float p) { return unit() < p; }

private:
    std::mt19937 engine_;
};

glm::vec3 hsvToRgb(float hue, float saturation, float value)
{
    const glm::vec3 k = glm::mod(glm::vec3{5.0f, 3.0f, 1.0f} + hue * 6.0f, 6.0f);
    const glm::vec3 ramp = glm::clamp(glm::min(k, 4.0f - k), 0.0f, 1.0f);
    return value * (1.0f - saturation * ramp);
}

// Bounds of the mesh's vertices under `transform`: exact (unlike transforming the corners of
// the object-space box), which matters for resting rotated tori exactly on the floor.
Bounds transformedBounds(const Mesh& mesh, const glm::mat4& transform)
{
    Bounds bounds;
    for (const Vertex& vertex : mesh.vertices)
        bounds.extend(glm::vec3(transform * glm::vec4(vertex.position, 1.0f)));
    return bounds;
}

Mesh embeddedObj(const char* path, const char* name)
{
    const std::optional<std::string_view> text = embeddedFile(path);
    // The build embeds these files; their absence is a build mistake, not a user's.
    ML_ASSERT(text.has_value());
    std::istringstream stream{std::string(*text)};
    Mesh mesh = loadObjStream(stream, path);
    mesh.name = name;
    return mesh;
}

enum class Shape { Box, Sphere, Cylinder, Cone, Torus, Bunny, Teapot };

const char* shapeName(Shape shape)
{
    switch (shape) {
    case Shape::Box: return "box";
    case Shape::Sphere: return "sphere";
    case Shape::Cylinder: return "cylinder";
    case Shape::Cone: return "cone";
    case Shape::Torus: return "torus";
    case Shape::Bunny: return "bunny";
    case Shape::Teapot: return "teapot";
    }
    return "object";
}

// Something to stand on the floor: its mesh, rotation and scale, before it has a place.
struct Item {
    Shape shape;
    std::size_t mesh;
    glm::vec3 rotateDegrees;
    glm::vec3 scale;
    Material material;
    std::optional<ObjectAnimation> animation{};  // its pivot or base filled in once placed
};

constexpr float kHalfExtent = 16.0f;  // objects stay within ±16 in X and Z
constexpr float kGap = 0.35f;         // the least free floor between two objects
constexpr int kPrimitiveCount = 128;
constexpr int kModelCount = 6;  // bunnies, and as many teapots
constexpr std::uint32_t kSceneSeed = 20240601u;
constexpr std::uint32_t kLightSeed = 7u;
constexpr std::uint32_t kDriftingLightSeed = 8u;
constexpr float kLightMarkerRadius = 0.08f;
// Teapots sway by this shear factor at most: the top of a 1.5-high teapot moves 0.2 sideways.
constexpr float kSwayAmplitude = 0.13f;
constexpr float kModelHeight = 1.5f;
// The two surfaces of revolution stand in the front row, left and right of the centre.
constexpr glm::vec2 kStaticVaseSpot{-3.0f, 9.0f};
constexpr glm::vec2 kDynamicVaseSpot{3.0f, 9.0f};

// Two vases of the same profile: one built on the CPU (frozen at t = 0), one whose surface the
// vertex shader moves with time (scene/Revolution.h). Placed before the crowd, which avoids them.
template <typename Placed>
void addSurfacesOfRevolution(Scene& scene, std::vector<Placed>& placed)
{
    RevolutionProfile profile;
    profile.radius = 0.45f;
    profile.height = 1.4f;
    profile.amplitude = 0.12f;
    profile.waves = 1.5f;
    profile.speed = 0.4f;
    const auto addVase = [&](const char* name, glm::vec2 spot, bool dynamic, glm::vec3 colour) {
        Mesh mesh = makeRevolutionMesh(profile, 0.0);
        mesh.name = name;
        scene.meshes.push_back(std::move(mesh));
        Material material;
        material.name = name;
        material.diffuse = colour;
        material.specular = glm::vec3{0.5f};
        material.shininess = 64.0f;
        scene.materials.push_back(material);
        Object object;
        object.name = name;
        object.mesh = scene.meshes.size() - 1;
        object.material = scene.materials.size() - 1;
        object.transform = glm::translate(glm::mat4{1.0f}, glm::vec3{spot.x, 0.0f, spot.y});
        if (dynamic)
            object.revolution = profile;
        scene.objects.push_back(std::move(object));
        placed.push_back({spot, profile.radius + profile.amplitude});
    };
    addVase("vase-static", kStaticVaseSpot, false, {0.85f, 0.75f, 0.55f});
    addVase("vase-dynamic", kDynamicVaseSpot, true, {0.55f, 0.75f, 0.85f});
}

}  // namespace

Scene makeDefaultScene()
{
    Scene scene;
    scene.source = "<default scene>";
    // Seen from the front at about 45°: at 16:9 the whole ±16 crowd fits with a small margin
    // and the floor's far edge stays in view.
    scene.camera.eye = {0.0f, 24.0f, 28.0f};
    scene.camera.lookAt = {0.0f, 0.0f, 3.0f};
    scene.camera.up = {0.0f, 1.0f, 0.0f};
    scene.camera.fovYDegrees = 45.0f;
    scene.camera.nearPlane = 0.1f;
    scene.camera.farPlane = 200.0f;
    scene.background = glm::vec3{0.0f};
    scene.ambient = glm::vec3{0.06f};
    scene.directional = DirectionalLight{{-1.0f, -2.0f, -1.0f}, glm::vec3{0.25f}, false};

    // The lights are light sets, not explicit lights, so that `--lights N` scales this scene.
    // Three quarters circle their spot, the rest drift about it; each light has a small
    // emissive sphere in its own colour that follows it.
    LightSet lights;
    lights.count = 192;
    lights.seed = kLightSeed;
    lights.type = LightType::Point;
    lights.boxMin = {-17.0f, 0.4f, -17.0f};
    lights.boxMax = {17.0f, 1.0f, 17.0f};
    lights.range = {3.5f, 5.0f};
    lights.intensity = {0.2f, 0.45f};
    lights.animation = OrbitAnimation{1.2f, 40.0f, 0.0f};
    scene.lightSets.push_back(lights);
    lights.count = 64;
    lights.seed = kDriftingLightSeed;
    // Up and down by 0.3 at most: the lights stay between 0.1 and 1.3 above the floor.
    lights.animation = DriftAnimation{{2.0f, 0.3f, 2.0f}, {9.0f, 4.0f, 13.0f}, 0.0f};
    scene.lightSets.push_back(lights);
    scene.lightMarkerRadius = kLightMarkerRadius;

    Mesh floorMesh = makePlane(40.0f, 40.0f);
    floorMesh.name = "floor";
    scene.meshes.push_back(std::move(floorMesh));
    Material floorMaterial;
    floorMaterial.name = "floor";
    floorMaterial.diffuse = glm::vec3{0.5f};
    floorMaterial.specular = glm::vec3{0.12f};
    floorMaterial.shininess = 24.0f;
    scene.materials.push_back(floorMaterial);
    scene.objects.push_back({"floor", 0, 0, glm::mat4{1.0f}});

    // One unit-sized mesh per shape; the transform gives each object its size.
    const auto addMesh = [&](Mesh mesh, const char* name) {
        mesh.name = name;
        scene.meshes.push_back(std::move(mesh));
        return scene.meshes.size() - 1;
    };
    const std::size_t boxMesh = addMesh(makeBox(glm::vec3{1.0f}), "box");
    const std::size_t sphereMesh = addMesh(makeSphere(0.5f), "sphere");
    const std::size_t cylinderMesh = addMesh(makeCylinder(0.5f, 1.0f), "cylinder");
    const std::size_t coneMesh = addMesh(makeCone(0.5f, 1.0f), "cone");
    // Tori differ in shape, not only in size, so each thickness is its own mesh.
    const std::size_t torusMeshes[3] = {addMesh(makeTorus(0.4f, 0.1f), "torus-thin"),
                                        addMesh(makeTorus(0.35f, 0.15f), "torus"),
                                        addMesh(makeTorus(0.3f, 0.2f), "torus-thick")};
    const std::size_t bunnyMesh = scene.meshes.size();
    scene.meshes.push_back(embeddedObj("assets/models/bunny-lowres.obj", "bunny"));
    const std::size_t teapotMesh = scene.meshes.size();
    scene.meshes.push_back(embeddedObj("assets/models/teapot-lowres.obj", "teapot"));

    Random random(kSceneSeed);
    const auto randomMaterial = [&](float specularChance) {
        Material material;
        material.diffuse = hsvToRgb(random.unit(), random.between(0.55f, 0.9f), random.between(0.55f, 0.9f));
        if (random.chance(specularChance)) {
            material.specular = glm::vec3{random.between(0.3f, 0.6f)};
            material.shininess = random.between(16.0f, 96.0f);
        }
        return material;
    };

    // The large models go first: they are the hardest to fit in later.
    std::vector<Item> items;
    for (int i = 0; i < 2 * kModelCount; ++i) {
        const bool bunny = i % 2 == 0;
        const std::size_t mesh = bunny ? bunnyMesh : teapotMesh;
        const Bounds bounds = scene.meshes[mesh].bounds();
        const float scale = kModelHeight / (bounds.max.y - bounds.min.y);
        // Teapots are glazed: always shiny.
        Material material = randomMaterial(bunny ? 0.3f : 1.0f);
        items.push_back({bunny ? Shape::Bunny : Shape::Teapot,
                         mesh,
                         {0.0f, random.between(0.0f, 360.0f), 0.0f},
                         glm::vec3{scale},
                         material});
        // Bunnies turn about their vertical axis, one way or the other; teapots sway from side
        // to side, each in its own direction and rhythm.
        if (bunny) {
            const float speed = random.between(20.0f, 50.0f) * (random.chance(0.5f) ? 1.0f : -1.0f);
            items.back().animation = SpinAnimation{{0.0f, 1.0f, 0.0f}, std::nullopt, speed, 0.0f};
        } else {
            const float heading = glm::radians(random.between(0.0f, 360.0f));
            items.back().animation = SwayAnimation{{std::cos(heading), 0.0f, std::sin(heading)},
                                                   kSwayAmplitude,
                                                   random.between(0.3f, 0.7f),
                                                   random.between(0.0f, 360.0f),
                                                   0.0f};
        }
    }
    for (int i = 0; i < kPrimitiveCount; ++i) {
        Item item{};
        item.shape = static_cast<Shape>(random.below(5));
        item.rotateDegrees = {0.0f, random.between(0.0f, 360.0f), 0.0f};
        const float height = random.between(0.4f, 1.6f);
        switch (item.shape) {
        case Shape::Box:
            item.mesh = boxMesh;
            item.scale = {random.between(0.4f, 1.4f), height, random.between(0.4f, 1.4f)};
            break;
        case Shape::Sphere:
            // Spheres bounce, squashed thin in X and Z while fast; their hop is at most about
            // twice their size.
            item.mesh = sphereMesh;
            item.scale = glm::vec3{height};
            item.animation = BounceAnimation{random.between(0.6f, 1.8f) * height, random.between(0.8f, 1.6f),
                                             random.unit(), 0.25f, 0.0f};
            break;
        case Shape::Cylinder: {
            item.mesh = cylinderMesh;
            const float diameter = random.between(0.4f, 1.2f);
            item.scale = {diameter, height, diameter};
            break;
        }
        case Shape::Cone: {
            item.mesh = coneMesh;
            const float diameter = random.between(0.5f, 1.3f);
            item.scale = {diameter, height, diameter};
            break;
        }
        default: {
            item.shape = Shape::Torus;
            item.mesh = torusMeshes[random.below(3)];
            // Outer diameter; standing tori roll on their rim, the others lie flat.
            item.scale = glm::vec3{random.between(0.8f, 1.6f)};
            if (random.chance(0.5f))
                item.rotateDegrees.x = 90.0f;
            break;
        }
        }
        item.material = randomMaterial(0.4f);
        items.push_back(item);
    }

    // Dart throwing: each object gets the first random spot where its footprint (the circle
    // around its rotated bounding box) keeps a gap to every object placed before it.
    struct Placed {
        glm::vec2 centre;
        float radius;
    };
    std::vector<Placed> placed;
    addSurfacesOfRevolution(scene, placed);
    int counters[7] = {};
    for (Item& item : items) {
        const Mesh& mesh = scene.meshes[item.mesh];
        const glm::mat4 unplaced = composeTransform(glm::vec3{0.0f}, item.rotateDegrees, item.scale);
        const Bounds bounds = transformedBounds(mesh, unplaced);
        const glm::vec2 halfSize = 0.5f * glm::vec2{bounds.max.x - bounds.min.x, bounds.max.z - bounds.min.z};
        float radius = glm::length(halfSize);
        // A swaying object leans out of its footprint by the shear at its top.
        if (item.animation && std::holds_alternative<SwayAnimation>(*item.animation))
            radius += kSwayAmplitude * (bounds.max.y - bounds.min.y);
        const float limit = kHalfExtent - std::max(halfSize.x, halfSize.y);
        glm::vec2 spot{0.0f};
        bool found = false;
        for (int attempt = 0; attempt < 10000 && !found; ++attempt) {
            spot = {random.between(-limit, limit), random.between(-limit, limit)};
            found = std::all_of(placed.begin(), placed.end(), [&](const Placed& other) {
                return glm::distance(spot, other.centre) >= radius + other.radius + kGap;
            });
        }
        // The counts above leave the floor far from full; a failure means someone changed them.
        ML_ASSERT(found);
        placed.push_back({spot, radius});

        // Move the bounding box's bottom centre onto the spot on the floor.
        const glm::vec3 bottomCentre{0.5f * (bounds.min.x + bounds.max.x), bounds.min.y,
                                     0.5f * (bounds.min.z + bounds.max.z)};
        const glm::vec3 translate = glm::vec3{spot.x, 0.0f, spot.y} - bottomCentre;
        const std::string name = shapeName(item.shape) + std::to_string(counters[static_cast<int>(item.shape)]++);
        item.material.name = name;
        scene.materials.push_back(item.material);
        Object object;
        object.name = name;
        object.mesh = item.mesh;
        object.material = scene.materials.size() - 1;
        object.transform = composeTransform(translate, item.rotateDegrees, item.scale);
        // Spinning about the footprint's centre keeps the object inside its footprint circle.
        if (item.animation)
            if (auto* spin = std::get_if<SpinAnimation>(&*item.animation))
                spin->pivot = glm::vec3{spot.x, 0.0f, spot.y};
        object.animation = item.animation;
        scene.objects.push_back(std::move(object));
    }
    return scene;
}

}  // namespace manylights
