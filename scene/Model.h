// What a model file (OBJ + MTL, glTF) contributes to a scene before it joins one: meshes whose
// sub-meshes index `materials`, placed instances, lights and embedded images, all in the
// model's own space. SceneLoader appends them to the Scene (offsetting the material indices)
// and multiplies the instances and lights by the object's transform.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/Scene.h"

namespace manylights {

struct ModelInstance {
    std::string name;           // the glTF node's name (or "nodes[i]"); the file name for an OBJ
    std::size_t mesh = 0;       // index into Model::meshes
    glm::mat4 transform{1.0f};  // the node's world matrix in the model
};

struct Model {
    std::vector<Mesh> meshes;  // SubMesh::material indexes Model::materials
    std::vector<Material> materials;
    std::vector<ModelInstance> instances;
    std::vector<Light> lights;         // in model space
    std::vector<NamedCamera> cameras;  // in model space, named after their nodes
    std::vector<EncodedImage> images;
};

}  // namespace manylights
