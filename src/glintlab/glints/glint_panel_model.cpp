#include "glintlab/glints/glint_panel_model.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "glintlab/glints/registry.h"

namespace glintlab {

std::vector<GlintPanelWidget> glint_panel_model(GlintDesc& desc) {
    const GlintModelDescriptor& model = glint_model(desc.model_id);
    std::vector<GlintPanelWidget> widgets;
    for (const GlintParam& p : model.params) {
        GlintPanelWidget w;
        w.key = p.key;
        w.type = p.type;
        w.ui = p.ui;
        w.min = p.min, w.max = p.max;
        // Sliders move in float steps: keep them off an open end.
        if (p.min_open) w.min = std::nextafter(static_cast<float>(p.min), INFINITY);
        if (p.max_open) w.max = std::nextafter(static_cast<float>(p.max), -INFINITY);
        w.integer_values = p.integer_values;
        if (p.type == GlintParamType::Enum) w.choices = p.choices;
        for (int v : p.integer_values) w.choices.push_back(fmt::format("{}", v));
        w.value = p.get(desc.params);
        const GlintParam* param = &p;
        GlintDesc* d = &desc;
        const double lo = w.min, hi = w.max;
        w.set = [param, d, lo, hi](const GlintParamValue& v) {
            GlintParamValue x = v;
            if (double* n = std::get_if<double>(&x); n && std::isfinite(*n))
                *n = std::clamp(*n, lo, hi);
            if (int* i = std::get_if<int>(&x)) {
                if (!param->integer_values.empty()) {
                    // Nearest allowed value.
                    int best = param->integer_values.front();
                    for (int c : param->integer_values)
                        if (std::abs(c - *i) < std::abs(best - *i)) best = c;
                    *i = best;
                } else {
                    *i = std::clamp(*i, static_cast<int>(lo), static_cast<int>(hi));
                }
            }
            if (param->accepts(x)) param->set(d->params, x);
        };
        widgets.push_back(std::move(w));
    }
    return widgets;
}

std::vector<GlintPanelColours> glint_panel_colours(GlintDesc& desc) {
    std::vector<GlintPanelColours> lists;
    for (const GlintExtraKey& k : glint_model(desc.model_id).extra_keys) {
        if (k.max_colours <= 0) continue;
        lists.push_back(
            {k.key, k.max_colours, &k.colour_count(desc.params), k.colours(desc.params)});
    }
    return lists;
}

}  // namespace glintlab
