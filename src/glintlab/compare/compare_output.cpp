// The files and tables of `glintlab compare`: metrics.json / .csv, the text
// table, the labelled grid and the false-colour difference images.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "glintlab/compare/compare.h"
#include "glintlab/core/error.h"

// stb_easy_font (Debian libstb-dev): a public-domain vector font that emits
// quads; only print() is used here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

namespace glintlab::compare {
namespace {

nlohmann::json number(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

std::string csv_number(double x) {
    return std::isfinite(x) ? fmt::format("{:.6g}", x) : std::string("nan");
}

// Draws `text` in white on a black background at (x0, y0), scaled by `scale`
// (stb_easy_font's glyphs are about 6 x 7 units, lines 10 units apart).
void draw_text(Image& image, int x0, int y0, const std::string& text, int scale) {
    std::vector<char> buffer(text.size() * 300 + 300);
    std::string s = text;
    const int quads =
        stb_easy_font_print(0.0f, 0.0f, s.data(), nullptr, buffer.data(), int(buffer.size()));
    // Each vertex: x, y, z (float) and 4 colour bytes; 4 vertices a quad.
    for (int q = 0; q < quads; ++q) {
        float v[4][4];
        std::memcpy(v, buffer.data() + size_t(q) * 64, 64);
        const float xa = std::min(v[0][0], v[2][0]), xb = std::max(v[0][0], v[2][0]);
        const float ya = std::min(v[0][1], v[2][1]), yb = std::max(v[0][1], v[2][1]);
        for (int y = int(ya * scale); y < int(yb * scale); ++y)
            for (int x = int(xa * scale); x < int(xb * scale); ++x) {
                const int px = x0 + x, py = y0 + y;
                if (px >= 0 && py >= 0 && px < image.width && py < image.height)
                    image.at(px, py) = glm::vec3(1.0f);
            }
    }
}

// Diverging colour of t in [-1, 1]: blue (-1), white (0), red (+1).
glm::vec3 diverging(float t) {
    t = std::clamp(std::isfinite(t) ? t : 0.0f, -1.0f, 1.0f);
    return t >= 0.0f ? glm::vec3(1.0f, 1.0f - t, 1.0f - t) : glm::vec3(1.0f + t, 1.0f + t, 1.0f);
}

// Colours are display values; write_png sRGB-encodes linear values, so
// decode them first.
Image false_colour(const std::vector<float>& t, int w, int h) {
    Image img(w, h);
    for (size_t i = 0; i < t.size(); ++i) {
        const glm::vec3 c = diverging(t[i]);
        img.pixels[i] = glm::vec3(srgb_decode(c.x), srgb_decode(c.y), srgb_decode(c.z));
    }
    return img;
}

// A false-colour difference image, enlarged (nearest) to at least 128
// pixels wide, over its legend: the colour bar from -1 to +1 and what its
// ends and centre mean.
Image false_colour_with_legend(const std::vector<float>& t, int w, int h, const std::string& low,
                               const std::string& high) {
    const Image img = false_colour(t, w, h);
    const int zoom = std::max(1, (128 + w - 1) / w);
    const int cw = w * zoom, bar = 8, text = 12;
    Image out(cw, h * zoom + 2 + bar + text, glm::vec3(0.0f));
    for (int y = 0; y < h * zoom; ++y)
        for (int x = 0; x < cw; ++x) out.at(x, y) = img.at(x / zoom, y / zoom);
    for (int x = 0; x < cw; ++x) {
        const glm::vec3 c = diverging(2.0f * (float(x) + 0.5f) / float(cw) - 1.0f);
        for (int y = 0; y < bar; ++y)
            out.at(x, h * zoom + 2 + y) =
                glm::vec3(srgb_decode(c.x), srgb_decode(c.y), srgb_decode(c.z));
    }
    const int ty = h * zoom + 2 + bar + 2;
    draw_text(out, 0, ty, low, 1);
    draw_text(out, cw / 2 - 3, ty, "0", 1);
    draw_text(out, std::max(0, cw - 6 * int(high.size())), ty, high, 1);
    return out;
}

std::string signed_percent(double x) {
    return std::isfinite(x) ? fmt::format("{:+.1f}%", 100.0 * x) : std::string("n/a");
}

}  // namespace

nlohmann::json CompareResult::to_json() const {
    nlohmann::json j;
    j["scene"] = scene;
    j["material"] = material;
    j["lights"] = lights;
    j["width"] = width, j["height"] = height, j["spp"] = spp;
    j["realizations"] = realizations, j["frames"] = frames;
    j["truth_realizations"] = truth_realizations;
    j["flicker_paths"] = flicker_paths;
    j["orbit_deg"] = orbit_deg;
    j["blur_sigma_px"] = blur_sigma_px;
    j["mask_pixels"] = mask_pixels;
    j["models"] = nlohmann::json::array();
    for (const ModelMetrics& m : models) {
        nlohmann::json r;
        r["model"] = m.model;
        r["compared"] = m.compared;
        if (!m.compared) {
            r["reason"] = m.reason;
            j["models"].push_back(r);
            continue;
        }
        r["reference"] = m.reference;
        r["backend"] = m.backend;
        r["truth"] = m.truth;
        r["facet_extent"] = m.facet_extent;
        r["mean_luminance"] = number(m.mean_luminance);
        r["mean_luminance_rel_se"] = number(m.mean_luminance_rel_se);
        r["mean_rel_err"] = number(m.mean_rel_err);
        r["mean_rel_err_se"] = number(m.mean_rel_err_se);
        r["blurred_rel_rmse"] = number(m.blurred_rel_rmse);
        r["pixel_variance"] = number(m.pixel_variance);
        r["variance_ratio"] = number(m.variance_ratio);
        r["sampling_variance"] = number(m.sampling_variance);
        r["structure_variance_ratio"] = number(m.structure_variance_ratio);
        r["wasserstein"] = number(m.wasserstein);
        r["flicker"] = number(m.flicker);
        r["flicker_se"] = number(m.flicker_se);
        r["flicker_ratio"] = number(m.flicker_ratio);
        r["flicker_ratio_se"] = number(m.flicker_ratio_se);
        r["sampling_flicker"] = number(m.sampling_flicker);
        r["seconds"] = number(m.seconds);
        r["nan_count"] = m.faults.nan;
        r["inf_count"] = m.faults.inf;
        r["negative_count"] = m.faults.negative;
        r["cut_fragments"] = m.cut_fragments;
        j["models"].push_back(r);
    }
    return j;
}

std::string CompareResult::to_csv() const {
    std::string s =
        "model,compared,reference,backend,truth,facet_extent,mean_luminance,mean_rel_err,mean_rel_"
        "err_se,"
        "blurred_rel_rmse,pixel_variance,variance_ratio,sampling_variance,structure_variance_ratio,"
        "wasserstein,flicker,flicker_se,flicker_ratio,flicker_ratio_se,"
        "sampling_flicker,seconds,nan_count,inf_count,negative_count,reason\n";
    for (const ModelMetrics& m : models) {
        if (!m.compared) {
            s += fmt::format("{},false,,,,,,,,,,,,,,,,,,,,,,,\"{}\"\n", m.model, m.reason);
            continue;
        }
        s += fmt::format(
            "{},true,{},{},\"{}\",\"{}\",{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},\n",
            m.model, m.reference, m.backend, m.truth, m.facet_extent, csv_number(m.mean_luminance),
            csv_number(m.mean_rel_err), csv_number(m.mean_rel_err_se),
            csv_number(m.blurred_rel_rmse), csv_number(m.pixel_variance),
            csv_number(m.variance_ratio), csv_number(m.sampling_variance),
            csv_number(m.structure_variance_ratio), csv_number(m.wasserstein),
            csv_number(m.flicker), csv_number(m.flicker_se), csv_number(m.flicker_ratio),
            csv_number(m.flicker_ratio_se), csv_number(m.sampling_flicker), csv_number(m.seconds),
            m.faults.nan, m.faults.inf, m.faults.negative);
    }
    return s;
}

std::string CompareResult::to_text() const {
    std::string s = fmt::format(
        "{}: material {}, lights {}, {}x{}, {} spp, {} realizations ({} of the truth), {} "
        "flicker paths of {} frames over {} deg, blur sigma {:.2g} px, {} material pixels\n",
        scene, material, lights, width, height, spp, realizations, truth_realizations,
        flicker_paths, frames, orbit_deg, blur_sigma_px, mask_pixels);
    s += fmt::format("{:<14} {:<4} {:>16} {:>9} {:>9} {:>10} {:>8} {:>14} {:>9} {:>12}\n", "model",
                     "dev", "mean err (se)", "blur rmse", "var ratio", "struct var", "W1",
                     "flicker x (se)", "time s", "nan/inf/neg");
    for (const ModelMetrics& m : models) {
        if (!m.compared) {
            s += fmt::format("{:<14} not compared: {}\n", m.model, m.reason);
            continue;
        }
        const std::string err = m.reference
                                    ? std::string("truth")
                                    : fmt::format("{} ({:.1f}%)", signed_percent(m.mean_rel_err),
                                                  100.0 * m.mean_rel_err_se);
        const std::string flicker =
            m.reference
                ? fmt::format("1 ({:.2g})", m.flicker > 0.0 ? m.flicker_se / m.flicker : 0.0)
                : fmt::format("{:.3g} ({:.2g})", m.flicker_ratio, m.flicker_ratio_se);
        s += fmt::format(
            "{:<14} {:<4} {:>16} {:>9.3g} {:>9.3g} {:>10.3g} {:>8.3g} {:>14} {:>9.3g} "
            "{:>4}/{}/{}\n",
            m.model, m.backend, err, m.blurred_rel_rmse, m.variance_ratio,
            m.structure_variance_ratio, m.wasserstein, flicker, m.seconds, m.faults.nan,
            m.faults.inf, m.faults.negative);
    }
    for (const ModelMetrics& m : models)
        if (m.compared && m.cut_fragments > 0)
            s += fmt::format(
                "warning: {} ({}): the OpenGL implementation cut the shading loops of {} "
                "fragments short over its renders (Mesa llvmpipe ends a shader's loops after "
                "65535 iterations in all): its images are too dark\n",
                m.model, m.backend, m.cut_fragments);
    s += "facet extents (under point and directional lights):\n";
    for (const ModelMetrics& m : models)
        if (m.compared) s += fmt::format("  {:<14} {}\n", m.model, m.facet_extent);
    return s;
}

void write_compare_outputs(const CompareResult& result, const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
        fail("compare -o {}: cannot create the output directory: {}", dir.string(), ec.message());
    auto write_text = [&](const std::string& name, const std::string& text) {
        const std::filesystem::path p = dir / name;
        std::ofstream out(p);
        out << text;
        if (!out) fail("compare -o {}: cannot write {}", dir.string(), p.string());
    };
    write_text("metrics.json", result.to_json().dump(2) + "\n");
    write_text("metrics.csv", result.to_csv());

    const int w = result.width, h = result.height;
    const ModelMetrics* truth = nullptr;
    for (const ModelMetrics& m : result.models)
        if (m.reference && !truth) truth = &m;

    std::vector<const ModelMetrics*> shown;
    for (const ModelMetrics& m : result.models) {
        if (!m.compared) continue;
        shown.push_back(&m);
        // Distinct file names for several truths (explicit, explicit_2, ...).
        std::string name = m.model;
        if (m.reference && &m != truth) {
            int n = 1;
            for (const ModelMetrics& o : result.models) {
                if (&o == &m) break;
                n += o.reference;
            }
            name += fmt::format("_{}", n);
        }
        write_exr(m.image, dir / (name + ".exr"));
        write_png(m.image, dir / (name + ".png"));
        if (m.reference) continue;
        const ModelMetrics* t = nullptr;
        for (const ModelMetrics& o : result.models)
            if (o.reference && o.truth == m.truth) t = &o;
        if (t == nullptr) continue;
        const double mean = std::max(t->mean_luminance, 1e-12);
        std::vector<float> d(m.mean_plane.values.size());
        for (size_t i = 0; i < d.size(); ++i)
            d[i] = result.mask[i]
                       ? float((m.mean_plane.values[i] - t->mean_plane.values[i]) / (2.0 * mean))
                       : 0.0f;
        // d = (model - truth) / (2 x the truth's image mean): +-1 is +-2 means.
        write_png(false_colour_with_legend(d, w, h, "-2x mean", "+2x mean"),
                  dir / (m.model + "_diff.png"));
        const Plane bm = gaussian_blur(m.mean_plane, result.blur_sigma_px);
        const Plane bt = gaussian_blur(t->mean_plane, result.blur_sigma_px);
        for (size_t i = 0; i < d.size(); ++i)
            d[i] = result.mask[i] && bt.values[i] > 0.0f
                       ? float((bm.values[i] - bt.values[i]) / bt.values[i] / 0.5)
                       : 0.0f;
        write_png(false_colour_with_legend(d, w, h, "-50%", "+50%"),
                  dir / (m.model + "_diff_blur.png"));
    }

    // The truths' numbers (1, 2, ... in row order), as the file names count them.
    int truths = 0;
    for (const ModelMetrics& m : result.models) truths += m.reference && m.compared;
    auto truth_number = [&](const ModelMetrics& m) {
        if (!m.reference) return 0;
        int n = 0;
        for (const ModelMetrics& o : result.models) {
            n += o.reference;
            if (&o == &m) return n;
        }
        return 0;
    };

    // The grid: each image upscaled (nearest) to at least 128 pixels wide,
    // three label lines under it.
    const int zoom = std::max(1, (128 + w - 1) / w);
    const int text_scale = 1, line = 10 * text_scale, label = 3 * line + 4, pad = 4;
    const int cw = w * zoom, ch = h * zoom;
    const int cols = std::min<int>(4, int(shown.size()));
    const int rows = (int(shown.size()) + cols - 1) / cols;
    Image grid(cols * (cw + pad) + pad, rows * (ch + label + pad) + pad, glm::vec3(0.0f));
    for (size_t i = 0; i < shown.size(); ++i) {
        const ModelMetrics& m = *shown[i];
        const int x0 = pad + int(i % size_t(cols)) * (cw + pad);
        const int y0 = pad + int(i / size_t(cols)) * (ch + label + pad);
        for (int y = 0; y < ch; ++y)
            for (int x = 0; x < cw; ++x) {
                const glm::vec3 c = m.image.at(x / zoom, y / zoom);
                grid.at(x0 + x, y0 + y) =
                    glm::vec3(std::isfinite(c.x) ? c.x : 0.0f, std::isfinite(c.y) ? c.y : 0.0f,
                              std::isfinite(c.z) ? c.z : 0.0f);
            }
        // Several truths (one per NDF or facet extent) are told apart by
        // number and by the models each is the truth of.
        const int number = truth_number(m);
        const std::string tag = truths > 1 && number > 0 ? fmt::format(" #{}", number) : "";
        draw_text(grid, x0, y0 + ch + 2, m.model + (m.backend == "gpu" ? " (gpu)" : "") + tag,
                  text_scale);
        draw_text(grid, x0, y0 + ch + 2 + line, fmt::format("{:.3g} s", m.seconds), text_scale);
        std::string third;
        if (m.reference) {
            third = "truth of";
            for (const ModelMetrics& o : result.models)
                if (!o.reference && o.compared && o.truth == m.truth) third += " " + o.model;
        } else {
            third = fmt::format("err {}  blur {:.2f}", signed_percent(m.mean_rel_err),
                                m.blurred_rel_rmse);
            if (truths > 1) {
                for (const ModelMetrics& o : result.models)
                    if (o.reference && o.truth == m.truth)
                        third += fmt::format(" vs #{}", truth_number(o));
            }
        }
        // stb_easy_font's glyphs are about 6 px wide: cut what the tile cannot hold.
        const size_t room = size_t(std::max(1, cw / 6));
        if (third.size() > room) third = third.substr(0, room - 2) + "..";
        draw_text(grid, x0, y0 + ch + 2 + 2 * line, third, text_scale);
    }
    write_png(grid, dir / "grid.png");
}

}  // namespace glintlab::compare
