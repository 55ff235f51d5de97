// The built-in scene used when no scene file is given (docs/cli.md): a floor with a crowd of
// primitives (the spheres bounce), spinning bunnies, swaying teapots and two vases (surfaces of
// revolution, one moved by the vertex shader), lit by two light sets of orbiting and drifting
// lights with markers, so that `--lights N` sweeps it.
#pragma once

#include "scene/Scene.h"

namespace manylights {

// Deterministic: every call returns the same scene (a fixed seed and no standard
// distributions, whose output differs between standard libraries).
Scene makeDefaultScene();

}  // namespace manylights
