// Each glint model's own parameters, read from its block of the glint
// material (ARCHITECTURE.md, "Model descriptors") by the model's read_params
// (registry.cpp).
// The variant is expanded from the list of models (model_list.h): its
// alternatives are the models' MParams structs (glints/m/m_params.h), in
// GlintModelId order, so alternative i is the parameters of model id i.
#pragma once

#include <variant>

#include "glintlab/glints/model_list.h"

#define GLINTLAB_MODEL_HEADER_KIND params
#include "glintlab/glints/model_headers.h"
#undef GLINTLAB_MODEL_HEADER_KIND

namespace glintlab {

namespace detail {
// std::variant<P...> of a list written `void, P0, P1, ...` (the X-macro's
// expansion has a leading comma per entry).
template <class Void, class... P>
struct GlintParamsVariant {
    using type = std::variant<P...>;
};
}  // namespace detail

#define GLINTLAB_MODEL_PARAMS_TYPE(m, M) , M##Params
using GlintModelParams =
    detail::GlintParamsVariant<void GLINTLAB_GLINT_MODELS(GLINTLAB_MODEL_PARAMS_TYPE)>::type;
#undef GLINTLAB_MODEL_PARAMS_TYPE

}  // namespace glintlab
