// Includes one header of every listed model (model_list.h): the file
// glints/m/m_KIND.h for each model m, KIND the macro
// GLINTLAB_MODEL_HEADER_KIND, which the includer defines (params or kernel).
// No include guard: included once per kind (model_params.h, glint_bxdf.cpp).
// The list is walked by position, each slot a computed #include of the
// model at that position; positions past the list's end are skipped.
#include "glintlab/glints/model_list.h"

#ifndef GLINTLAB_MODEL_HEADER_KIND
#error "define GLINTLAB_MODEL_HEADER_KIND (the header suffix) before including model_headers.h"
#endif

#ifndef GLINTLAB_MODEL_HEADER_AT
// The names, comma-separated (one trailing comma), and the one at position k.
#define GLINTLAB_MODEL_NAME_COMMA(m, M) m,
#define GLINTLAB_MODEL_NAMES GLINTLAB_GLINT_MODELS(GLINTLAB_MODEL_NAME_COMMA)
#define GLINTLAB_MODEL_FIRST_(a, ...) a
#define GLINTLAB_MODEL_FIRST(...) GLINTLAB_MODEL_FIRST_(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_0(...) __VA_ARGS__
#define GLINTLAB_MODEL_SKIP_1(a, ...) __VA_ARGS__
#define GLINTLAB_MODEL_SKIP_2(a, ...) GLINTLAB_MODEL_SKIP_1(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_3(a, ...) GLINTLAB_MODEL_SKIP_2(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_4(a, ...) GLINTLAB_MODEL_SKIP_3(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_5(a, ...) GLINTLAB_MODEL_SKIP_4(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_6(a, ...) GLINTLAB_MODEL_SKIP_5(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_7(a, ...) GLINTLAB_MODEL_SKIP_6(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_8(a, ...) GLINTLAB_MODEL_SKIP_7(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_9(a, ...) GLINTLAB_MODEL_SKIP_8(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_10(a, ...) GLINTLAB_MODEL_SKIP_9(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_11(a, ...) GLINTLAB_MODEL_SKIP_10(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_12(a, ...) GLINTLAB_MODEL_SKIP_11(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_13(a, ...) GLINTLAB_MODEL_SKIP_12(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_14(a, ...) GLINTLAB_MODEL_SKIP_13(__VA_ARGS__)
#define GLINTLAB_MODEL_SKIP_15(a, ...) GLINTLAB_MODEL_SKIP_14(__VA_ARGS__)
#define GLINTLAB_MODEL_APPLY(f, ...) f(__VA_ARGS__)  // f applied to the expanded list
#define GLINTLAB_MODEL_AT(k) \
    GLINTLAB_MODEL_FIRST(GLINTLAB_MODEL_APPLY(GLINTLAB_MODEL_SKIP_##k, GLINTLAB_MODEL_NAMES))
// "glintlab/glints/m/m_KIND.h" of the model at position k.
#define GLINTLAB_MODEL_STRING_(x) #x
#define GLINTLAB_MODEL_STRING(x) GLINTLAB_MODEL_STRING_(x)
// (Unformatted: a space would enter the path.)
// clang-format off
#define GLINTLAB_MODEL_PATH_(m, kind) GLINTLAB_MODEL_STRING(glintlab/glints/m/m##_##kind.h)
// clang-format on
#define GLINTLAB_MODEL_PATH(m, kind) GLINTLAB_MODEL_PATH_(m, kind)
#define GLINTLAB_MODEL_HEADER_AT(k) \
    GLINTLAB_MODEL_PATH(GLINTLAB_MODEL_AT(k), GLINTLAB_MODEL_HEADER_KIND)
#endif

#if GLINTLAB_GLINT_MODEL_COUNT > 16
#error "model_headers.h has 16 slots: add slots (and GLINTLAB_MODEL_SKIP_k) for more models"
#endif
// clang-format off
#if GLINTLAB_GLINT_MODEL_COUNT > 0
#include GLINTLAB_MODEL_HEADER_AT(0)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 1
#include GLINTLAB_MODEL_HEADER_AT(1)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 2
#include GLINTLAB_MODEL_HEADER_AT(2)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 3
#include GLINTLAB_MODEL_HEADER_AT(3)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 4
#include GLINTLAB_MODEL_HEADER_AT(4)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 5
#include GLINTLAB_MODEL_HEADER_AT(5)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 6
#include GLINTLAB_MODEL_HEADER_AT(6)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 7
#include GLINTLAB_MODEL_HEADER_AT(7)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 8
#include GLINTLAB_MODEL_HEADER_AT(8)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 9
#include GLINTLAB_MODEL_HEADER_AT(9)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 10
#include GLINTLAB_MODEL_HEADER_AT(10)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 11
#include GLINTLAB_MODEL_HEADER_AT(11)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 12
#include GLINTLAB_MODEL_HEADER_AT(12)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 13
#include GLINTLAB_MODEL_HEADER_AT(13)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 14
#include GLINTLAB_MODEL_HEADER_AT(14)
#endif
#if GLINTLAB_GLINT_MODEL_COUNT > 15
#include GLINTLAB_MODEL_HEADER_AT(15)
#endif
// clang-format on
