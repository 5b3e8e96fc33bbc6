// Shared helpers of the OpenGL tests: one headless context per test binary
// (EGL displays are per process), skipped with the reason when no EGL driver
// can give OpenGL 4.5.
#pragma once

#include <memory>
#include <string>

#include "glintlab/core/error.h"
#include "glintlab/gl/gl_context.h"

namespace glintlab::testing {

// The process-wide context, or null with *why set.
inline HeadlessContext* shared_gl_context(std::string* why) {
    static std::string reason;
    static std::unique_ptr<HeadlessContext> context = [] {
        try {
            return std::make_unique<HeadlessContext>();
        } catch (const Error& e) {
            reason = e.what();
            return std::unique_ptr<HeadlessContext>();
        }
    }();
    if (context) context->make_current();
    *why = reason;
    return context.get();
}

}  // namespace glintlab::testing

// Skips the current test when there is no OpenGL 4.5 context.
#define GLINTLAB_REQUIRE_GL()                                              \
    do {                                                                   \
        std::string why_;                                                  \
        if (glintlab::testing::shared_gl_context(&why_) == nullptr)        \
            GTEST_SKIP() << "no OpenGL 4.5 context through EGL: " << why_; \
    } while (0)
