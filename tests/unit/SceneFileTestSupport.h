// What the scene-file tests share: the test data's scene folder, a scene parsed from text as
// if read from scene.json there, and the message of the error a bad one gives.
#pragma once

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/Error.h"
#include "scene/SceneLoader.h"

namespace manylights::test {

inline const std::filesystem::path kSceneDir = std::filesystem::path(MANYLIGHTS_TEST_DATA_DIR) / "scene";

inline Scene parse(const std::string& json) { return parseScene(json, "scene.json", kSceneDir); }

// The message of the Error that parsing `json` throws; a test failure if it throws none.
inline std::string errorOf(const std::string& json)
{
    try {
        parse(json);
    } catch (const Error& e) {
        return e.what();
    }
    ADD_FAILURE() << "no error for " << json;
    return {};
}

// A path under the scene folder as the loader's messages write it.
inline std::string resolved(const std::string& relative) { return (kSceneDir / relative).lexically_normal().string(); }

}  // namespace manylights::test
