// Per-object material uniforms and the surface a mesh fragment describes.
layout(location = 10) uniform vec3 materialDiffuse;
layout(location = 11) uniform vec3 materialSpecular;
layout(location = 12) uniform float materialShininess;
layout(location = 13) uniform vec3 materialEmissive;

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec2 uv;

Surface meshSurface()
{
    Surface s;
    s.position = worldPosition;
    s.normal = normalize(worldNormal);
    s.diffuse = materialDiffuse;
    s.specular = materialSpecular;
    s.shininess = materialShininess;
    s.emissive = materialEmissive;
    return s;
}
