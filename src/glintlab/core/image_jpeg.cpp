// JPEG through libjpeg-turbo (Debian's libjpeg62-turbo).
//
// JPEG used to go through stb_image like PNG. The image fuzzer found three
// defects in stb's JPEG decoder (docs/VALIDATION.md "Fuzzing"; inputs in
// fuzz/regressions/image/: a write past its Huffman arrays, a read of uninitialised tables,
// and an undefined shift in its entropy decoder); the first two were caught
// by walking the file before stb ran, the third sits inside the bit reader
// where no walk can reach it. libjpeg-turbo is the reference decoder of the
// format (ITU-T T.81), fuzzed continuously upstream, and reports corrupt
// data instead of guessing; so JPEG is read here and stb keeps PNG.
//
// libjpeg reports a fatal error through error_exit, which must not return.
// It leaves through longjmp to the setjmp in decode(); no C++ object with a
// destructor lives in the frames it skips (libjpeg's own, and the two
// callbacks below, which format into a plain char array), and everything
// decode() owns is declared before the setjmp.
#include <algorithm>
#include <climits>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

// After the standard headers: jpeglib.h needs FILE and size_t declared.
#include <jerror.h>
#include <jpeglib.h>

#include "glintlab/core/error.h"
#include "glintlab/core/image_formats.h"
#include "glintlab/core/memory_limit.h"

namespace glintlab::image_formats {
namespace {

// A progressive file may hold any number of scans, and each one passes over
// the whole coefficient buffer: a small file of many tiny scans makes the
// decode quadratic (a known denial of service of every progressive JPEG
// decoder). A real encoder writes ~10 scans (libjpeg's default script for
// colour images has 10); T.81 needs at most one per component, spectral
// band and bit of successive approximation. libjpeg-turbo's own fuzzers and
// tools cap it at 500 (TJPARAM_SCANLIMIT, djpeg -maxscans); so do we.
constexpr int kMaxScans = 500;

struct JpegErrorState {
    jpeg_error_mgr manager;  // first: libjpeg passes a pointer to it
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX];
};

struct JpegProgress {
    jpeg_progress_mgr manager;  // first: libjpeg passes a pointer to it
    JpegErrorState* errors;
};

[[noreturn]] void on_error(j_common_ptr cinfo) {
    auto* state = reinterpret_cast<JpegErrorState*>(cinfo->err);
    (*cinfo->err->format_message)(cinfo, state->message);
    std::longjmp(state->jump, 1);
}

// Warnings (level -1) are corrupt data that libjpeg would paper over
// (a truncated file decoded with grey rows, a bad Huffman code, a scan
// missing): a silently wrong image, so they are errors here. Only the
// warnings about metadata this reader does not use are let pass. Trace
// messages (level >= 0) are ignored.
void on_message(j_common_ptr cinfo, int level) {
    if (level >= 0) return;
    const int code = cinfo->err->msg_code;
    if (code == JWRN_ADOBE_XFORM || code == JWRN_JFIF_MAJOR || code == JWRN_BOGUS_ICC) return;
    on_error(cinfo);
}

void on_progress(j_common_ptr cinfo) {
    auto* progress = reinterpret_cast<JpegProgress*>(cinfo->progress);
    const int scan = reinterpret_cast<j_decompress_ptr>(cinfo)->input_scan_number;
    if (scan > kMaxScans) {
        std::snprintf(progress->errors->message, sizeof progress->errors->message,
                      "more than %d scans (a progressive file of many tiny scans; corrupt or "
                      "hostile)",
                      kMaxScans);
        std::longjmp(progress->errors->jump, 1);
    }
}

// The header's facts, read before any pixel is decoded.
struct JpegHeader {
    int width = 0, height = 0, components = 0;
    bool progressive = false;
    J_COLOR_SPACE color_space = JCS_UNKNOWN;
};

// Decodes `bytes` to 8-bit RGB. `check_header` runs between the header and
// the decode (it throws to refuse the size); it is called from outside
// libjpeg, so its exception unwinds only C++ frames. Returns false with
// `message` set on a libjpeg error.
// The caller's header check runs in its own frame: inlined into decode(), its
// std::string work would keep locals in registers across the setjmp, which
// GCC flags at -O1 (-Wclobbered; the ASan tree) and longjmp could restore
// stale.
template <class CheckHeader>
[[gnu::noinline]] bool call_header_check(CheckHeader& check_header, const JpegHeader& header) {
    return check_header(header);
}

template <class CheckHeader>
bool decode(const std::string& bytes, CheckHeader check_header, std::vector<uint8_t>& rgb,
            JpegHeader& header, std::string& message) {
    jpeg_decompress_struct cinfo;
    JpegErrorState errors;
    JpegProgress progress;
    JSAMPROW row = nullptr;
    std::memset(&cinfo, 0, sizeof cinfo);
    cinfo.err = jpeg_std_error(&errors.manager);
    errors.manager.error_exit = on_error;
    errors.manager.emit_message = on_message;
    errors.message[0] = '\0';
    progress.manager.progress_monitor = on_progress;
    progress.errors = &errors;
    if (setjmp(errors.jump)) {
        message = errors.message;
        jpeg_destroy_decompress(&cinfo);
        return false;
    }
    jpeg_create_decompress(&cinfo);
    cinfo.progress = &progress.manager;
    // libjpeg's own allocations are bounded by the memory limit as well
    // (it checks max_memory_to_use before each large allocation).
    cinfo.mem->max_memory_to_use = long(std::min<uint64_t>(memory_limit(), uint64_t(LONG_MAX)));
    jpeg_mem_src(&cinfo, reinterpret_cast<const unsigned char*>(bytes.data()),
                 static_cast<unsigned long>(bytes.size()));
    jpeg_read_header(&cinfo, TRUE);
    header.width = int(cinfo.image_width);
    header.height = int(cinfo.image_height);
    header.components = cinfo.num_components;
    header.progressive = cinfo.progressive_mode;
    header.color_space = cinfo.jpeg_color_space;
    if (!call_header_check(check_header, header)) {
        jpeg_destroy_decompress(&cinfo);
        return true;  // refused by the caller, who reports why
    }
    cinfo.out_color_space = JCS_RGB;  // libjpeg expands greyscale itself
    cinfo.dct_method = JDCT_ISLOW;    // the exact integer IDCT (the default)
    jpeg_start_decompress(&cinfo);
    const size_t stride = size_t(cinfo.output_width) * 3;
    try {
        rgb.resize(stride * cinfo.output_height);
    } catch (...) {
        jpeg_destroy_decompress(&cinfo);
        throw;
    }
    while (cinfo.output_scanline < cinfo.output_height) {
        row = rgb.data() + stride * cinfo.output_scanline;
        jpeg_read_scanlines(&cinfo, &row, 1);
    }
    jpeg_finish_decompress(&cinfo);
    jpeg_destroy_decompress(&cinfo);
    return true;
}

}  // namespace

Image read_jpeg(const std::string& bytes, const std::filesystem::path& path) {
    std::vector<uint8_t> rgb;
    JpegHeader header;
    std::string message;
    std::string refused;
    auto check_header = [&](const JpegHeader& h) {
        if (h.color_space == JCS_CMYK || h.color_space == JCS_YCCK) {
            refused = fmt::format(
                "{}: cannot read JPEG file: it is a {} image (4 components); only greyscale and "
                "colour (YCbCr/RGB) JPEG files are read",
                path.string(), h.color_space == JCS_CMYK ? "CMYK" : "YCCK");
            return false;
        }
        // Per pixel beyond the Image: the 3-byte RGB rows decoded into, and
        // for a progressive file libjpeg's whole-image coefficient buffer,
        // 2 bytes per component (64 coefficients of 16 bits per 8x8 block).
        const uint64_t decoder_bytes = 3 + (h.progressive ? 2 * uint64_t(h.components) : 0);
        try {
            require_image_memory(path, "JPEG image", h.width, h.height, decoder_bytes);
        } catch (const Error& e) {
            refused = e.what();
            return false;
        }
        return true;
    };
    const bool decoded = decode(bytes, check_header, rgb, header, message);
    if (!refused.empty()) throw Error(refused);
    if (!decoded) fail("{}: cannot read JPEG file: {} (libjpeg-turbo)", path.string(), message);

    Image image(header.width, header.height);
    float table[256];  // 256 codes: decode each once
    for (int v = 0; v < 256; ++v) table[v] = srgb_decode(float(v) / 255.0f);
    for (size_t i = 0; i < 3 * image.pixels.size(); ++i)
        image.pixels[i / 3][int(i % 3)] = table[rgb[i]];
    return image;
}

}  // namespace glintlab::image_formats
