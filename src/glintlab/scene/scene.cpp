#include "glintlab/scene/scene.h"

namespace glintlab {

const char* material_type_name(MaterialDesc::Type type) {
    switch (type) {
        case MaterialDesc::Type::Diffuse:
            return "diffuse";
        case MaterialDesc::Type::Conductor:
            return "conductor";
        case MaterialDesc::Type::Dielectric:
            return "dielectric";
        case MaterialDesc::Type::Plastic:
            return "plastic";
        case MaterialDesc::Type::Glint:
            return "glint";
    }
    return "unknown";
}

}  // namespace glintlab
