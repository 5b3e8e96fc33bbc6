// The model descriptors of the list of models (model_list.h), each defined in
// its own folder (<model>/<model>_descriptor.cpp), checked against the
// GlintModelId order. Adding a model: docs/ADDING_A_MODEL.md.
#include "glintlab/glints/model_list.h"

#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {

#define GLINTLAB_DECLARE_DESCRIPTOR(model, Model) GlintModelDescriptor model##_descriptor();
GLINTLAB_GLINT_MODELS(GLINTLAB_DECLARE_DESCRIPTOR)
#undef GLINTLAB_DECLARE_DESCRIPTOR

const std::vector<GlintModelDescriptor>& glint_model_list() {
    static const std::vector<GlintModelDescriptor> list = [] {
#define GLINTLAB_DESCRIPTOR(model, Model) model##_descriptor(),
        std::vector<GlintModelDescriptor> l = {GLINTLAB_GLINT_MODELS(GLINTLAB_DESCRIPTOR)};
#undef GLINTLAB_DESCRIPTOR
        for (size_t i = 0; i < l.size(); ++i)
            if (static_cast<size_t>(l[i].id) != i)
                fail("internal error: glint model \"{}\" is listed out of GlintModelId order",
                     l[i].name);
        return l;
    }();
    return list;
}

}  // namespace glintlab
