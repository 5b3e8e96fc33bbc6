// `smooth` has no validation suite of its own (model_list.h): it is the limit
// the other models' suites compare against.
#include "glintlab/glints/validation_suites.h"

namespace glintlab {

ValidationSuiteRunner smooth_validation_suite() {
    return {};
}

}  // namespace glintlab
