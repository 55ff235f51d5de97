// The built-in default scene, made once per test binary: building it (meshes, 143 objects,
// 256 lights) costs more than most of the tests that inspect it.
#pragma once

#include "scene/DefaultScene.h"
#include "scene/Scene.h"

namespace manylights::test {

inline const Scene& sharedDefaultScene()
{
    static const Scene scene = makeDefaultScene();
    return scene;
}

}  // namespace manylights::test
