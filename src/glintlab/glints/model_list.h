// The list of glint models, in GlintModelId order: the one line a new model
// adds here (docs/ADDING_A_MODEL.md). GLINTLAB_GLINT_MODELS(X) expands X(m)
// for each model m, whose folder glints/m/ defines
//   GlintModelDescriptor m_descriptor();         m_descriptor.cpp (runtime library)
//   ValidationSuiteRunner m_validation_suite();  validate_m.cpp (research library)
// and, when the model has a GPU back end, the hooks its descriptor names
// (GLINTLAB_GPU_HOOKS). model_list.cpp and validation_suites.cpp expand the
// list; nothing else names every model.
#pragma once

#define GLINTLAB_GLINT_MODELS(X) \
    X(smooth)                    \
    X(deliot2023)                \
    X(zirr2016)                  \
    X(chermain2020)              \
    X(explicit)                  \
    X(jakob2014)                 \
    X(kneiphof2025)              \
    X(wang2020)
