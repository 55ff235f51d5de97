// Per-draw-item records (render/scene/GpuScene.h: GpuInstance), one storage buffer for the whole
// scene, written once per frame. GpuScene draws runs of items that share a mesh range with one
// instanced draw; record instanceBase + gl_InstanceID belongs to the instance being drawn.
// The base is a uniform rather than gl_BaseInstance, which needs GL 4.6 or
// ARB_shader_draw_parameters: this way the shaders run on any GL 4.5 core driver.
// SSBO binding 8 and uniform location 33 (lib/locations.glsl) are in issue 6's ranges.
#include "lib/bindings.glsl"
#include "lib/locations.glsl"
struct Instance {
    mat4 model;
    vec4 normalMatrix[3];   // columns of the inverse-transpose of the model's upper 3x3 (w unused)
    vec4 diffuse;           // rgb, w opacity (coverage before maps and vertex colours)
    vec4 specularShininess; // rgb specular, w shininess
    vec4 emissive;          // rgb, w alpha cutoff (read by alpha-masked variants only)
    vec4 specularTint;      // rgb base colour · metallic (scene/Scene.h), w unused
};

layout(std430, binding = INSTANCES_BUFFER_BINDING) readonly buffer Instances {
    Instance instances[];
};

layout(location = INSTANCE_BASE_LOCATION) uniform int instanceBase;

Instance currentInstance()
{
    return instances[instanceBase + gl_InstanceID];
}

mat3 instanceNormalMatrix(Instance instance)
{
    return mat3(instance.normalMatrix[0].xyz, instance.normalMatrix[1].xyz, instance.normalMatrix[2].xyz);
}
