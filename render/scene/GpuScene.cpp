#include "render/scene/GpuScene.h"

namespace manylights {

GpuScene::GpuScene(const Scene& scene, const std::vector<Light>& lights, const DriverChoices& driver)
    : scene_(scene),
      lights_(lights, scene.attenuationThreshold, driver),
      draws_(scene, lights_.rest(), driver),  // the markers follow the lights in the lights' order
      frame_(scene, lights.size()),
      environment_(scene.environment ? EnvironmentLight(*scene.environment) : EnvironmentLight()),
      features_{.scene = sceneFeaturesOf(lights, scene.directional), .policy = shaderPolicyOf(driver)}
{
    features_.scene.specularExponents = draws_.specularExponents();
    features_.scene.blinnPhong = draws_.drawsModel(ShadingModel::BlinnPhong);
    features_.scene.metallicRoughness = draws_.drawsModel(ShadingModel::MetallicRoughness);
    features_.scene.environment = environment_.present();
    setTime(0.0);
    setViewport(1, 1);
}

void GpuScene::bind() const
{
    draws_.bind();
    frame_.bind();
    lights_.bind();
    environment_.bind();
}

std::vector<GpuScene::TransparentLayer> GpuScene::transparentLayersBackToFront() const
{
    return draws_.transparentLayersBackToFront(glm::vec3(frameUniforms().eye), glm::vec3(frameUniforms().viewAxis));
}

void GpuScene::setViewport(int width, int height)
{
    frame_.setViewport(width, height);
    reorderDraws();
}

void GpuScene::setCamera(const Camera& camera)
{
    // The viewer sets its camera every frame; one that did not move needs no new draw order
    // and instance records.
    if (frame_.setCamera(camera))
        reorderDraws();
}

void GpuScene::setTime(double t)
{
    lights_.pose(t);
    draws_.pose(t, lights_);
    frame_.setTime(t);
    reorderDraws();
}

void GpuScene::reorderDraws()
{
    draws_.order(glm::vec3(frameUniforms().eye), glm::vec3(frameUniforms().viewAxis));
    draws_.writeInstances();
}

LightingFeatures GpuScene::lightingFeatures() const
{
    LightingFeatures features = features_;
    features.scene.directionalShadow = frame_.directionalShadow();
    features.scene.ambientOcclusion = frame_.ambientOcclusion();
    return features;
}

}  // namespace manylights
