// Each glint model's own parameters, read from its block of the glint
// material (ARCHITECTURE.md §4) by the model's read_params (registry.cpp).
// A closed set: add the model's parameter struct to the variant.
#pragma once

#include <variant>

#include "glintlab/glints/chermain2020/chermain2020_params.h"
#include "glintlab/glints/deliot2023/deliot2023_params.h"
#include "glintlab/glints/explicit/explicit_params.h"
#include "glintlab/glints/jakob2014/jakob2014_params.h"
#include "glintlab/glints/kneiphof2025/kneiphof2025_params.h"
#include "glintlab/glints/wang2020/wang2020_params.h"
#include "glintlab/glints/zirr2016/zirr2016_params.h"

namespace glintlab {

struct SmoothParams {};  // `smooth` has no parameters of its own

using GlintModelParams =
    std::variant<SmoothParams, Deliot2023Params, Zirr2016Params, Chermain2020Params,
                 Jakob2014Params, Kneiphof2025Params, ExplicitParams, Wang2020Params>;

}  // namespace glintlab
