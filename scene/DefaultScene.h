// The built-in scene used when no scene file is given (SPEC.md §3): a floor with a crowd of
// primitives, bunnies and teapots, lit by one light set so that `--lights N` sweeps it.
#pragma once

#include "scene/Scene.h"

namespace manylights {

// Deterministic: every call returns the same scene (a fixed seed and no standard
// distributions, whose output differs between standard libraries).
Scene makeDefaultScene();

}  // namespace manylights
