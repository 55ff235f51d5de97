// The fixture of the GL tests: one headless debug context per test suite (the synchronous
// error callback aborts on any GL error), and a check that no error is pending after each
// test.
#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "gl/Debug.h"
#include "platform/HeadlessContext.h"

namespace manylights {

class GlContextTest : public ::testing::Test {
protected:
    static void SetUpTestSuite() { context_ = std::make_unique<HeadlessContext>(ContextOptions{.debug = true}); }
    static void TearDownTestSuite() { context_.reset(); }
    void TearDown() override { gl::checkNoError("end of test"); }

    static const HeadlessContext& context() { return *context_; }

private:
    inline static std::unique_ptr<HeadlessContext> context_;
};

}  // namespace manylights
