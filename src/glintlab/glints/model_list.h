// The list of glint models, in GlintModelId order: the one line a new model
// adds here (docs/ADDING_A_MODEL.md). GLINTLAB_GLINT_MODELS(X) expands
// X(m, M) for each model, m its name and folder (glints/m/), M the same name
// capitalised: its GlintModelId enumerator. The folder defines
//   struct MParams;                              m_params.h (its parameters)
//   struct MKernel;                              m_kernel.h (GlintBxdf's hooks)
//   GlintModelDescriptor m_descriptor();         m_descriptor.cpp (runtime library)
//   ValidationSuiteRunner m_validation_suite();  validate_m.cpp (research library)
// and, when the model has a GPU back end or a `glintlab export`, the hooks
// its descriptor names (GLINTLAB_GPU_HOOKS, GLINTLAB_EXPORT_HOOK). Everything
// that names every model is expanded from this list: the GlintModelId enum
// and the GlintModelParams variant (glint_desc.h, model_params.h), GlintBxdf's
// dispatch (glint_bxdf.cpp), the descriptors (model_list.cpp) and the
// validation suites (validation_suites.cpp); the headers are included by
// model_headers.h.
#pragma once

#define GLINTLAB_GLINT_MODELS(X)  \
    X(smooth, Smooth)             \
    X(deliot2023, Deliot2023)     \
    X(zirr2016, Zirr2016)         \
    X(chermain2020, Chermain2020) \
    X(explicit, Explicit)         \
    X(jakob2014, Jakob2014)       \
    X(kneiphof2025, Kneiphof2025) \
    X(wang2020, Wang2020)

// The number of models, usable in #if: (0 +1 +1 ...).
#define GLINTLAB_GLINT_MODEL_PLUS_ONE(m, M) +1
#define GLINTLAB_GLINT_MODEL_COUNT (0 GLINTLAB_GLINT_MODELS(GLINTLAB_GLINT_MODEL_PLUS_ONE))
