// The list of glint models: the only place that names every model's
// descriptor (each defined in its own folder, <model>/<model>_descriptor.cpp).
// Order = GlintModelId order. Adding a model: docs/ADDING_A_MODEL.md.
#include <vector>

#include "glintlab/core/error.h"
#include "glintlab/glints/glint_model_descriptor.h"

namespace glintlab {

GlintModelDescriptor smooth_descriptor();
GlintModelDescriptor deliot2023_descriptor();
GlintModelDescriptor zirr2016_descriptor();
GlintModelDescriptor chermain2020_descriptor();
GlintModelDescriptor explicit_descriptor();
GlintModelDescriptor jakob2014_descriptor();
GlintModelDescriptor kneiphof2025_descriptor();
GlintModelDescriptor wang2020_descriptor();

const std::vector<GlintModelDescriptor>& glint_model_list() {
    static const std::vector<GlintModelDescriptor> list = [] {
        std::vector<GlintModelDescriptor> l = {
            smooth_descriptor(),       deliot2023_descriptor(), zirr2016_descriptor(),
            chermain2020_descriptor(), explicit_descriptor(),   jakob2014_descriptor(),
            kneiphof2025_descriptor(), wang2020_descriptor(),
        };
        for (size_t i = 0; i < l.size(); ++i)
            if (static_cast<size_t>(l[i].id) != i)
                fail("internal error: glint model \"{}\" is listed out of GlintModelId order",
                     l[i].name);
        return l;
    }();
    return list;
}

}  // namespace glintlab
