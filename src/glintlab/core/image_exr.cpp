// OpenEXR reading and writing through the generic InputFile/FrameBuffer API,
// which decodes every compression (including lossy DWAA/DWAB/B44 and PIZ)
// and converts half channels to float for us.
#include <algorithm>
#include <cstdint>
#include <exception>
#include <fstream>
#include <string>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfRgbaFile.h>

#include "glintlab/core/error.h"
#include "glintlab/core/image_formats.h"
#include "glintlab/core/memory_limit.h"

namespace glintlab::image_formats {
namespace {

std::string channel_names(const Imf::ChannelList& channels) {
    std::string names;
    for (auto it = channels.begin(); it != channels.end(); ++it) {
        if (!names.empty()) names += ", ";
        names += it.name();
    }
    return names.empty() ? "none" : names;
}

struct Window {
    int x0, y0, width, height;
};

Window window_of(const Imath::Box2i& box) {
    return {box.min.x, box.min.y, box.max.x - box.min.x + 1, box.max.y - box.min.y + 1};
}

// The image is the display window; the data window may be offset from it,
// smaller (uncovered pixels stay black) or larger (the overhang is cropped).
Image place_in_display_window(const std::vector<glm::vec3>& data, Window dw, Window display) {
    Image image(display.width, display.height);
    for (int y = 0; y < dw.height; ++y) {
        const int iy = dw.y0 + y - display.y0;
        if (iy < 0 || iy >= display.height) continue;
        for (int x = 0; x < dw.width; ++x) {
            const int ix = dw.x0 + x - display.x0;
            if (ix < 0 || ix >= display.width) continue;
            image.at(ix, iy) = data[size_t(y) * size_t(dw.width) + size_t(x)];
        }
    }
    return image;
}

// Luminance/chroma files (Y + RY/BY, subsampled chroma) need the RGBA
// interface's colour conversion; it delivers half precision, which is all
// such files store anyway.
std::vector<glm::vec3> read_luminance_chroma(const std::filesystem::path& path, Window dw) {
    Imf::RgbaInputFile file(path.c_str());
    std::vector<Imf::Rgba> rgba(size_t(dw.width) * size_t(dw.height));
    // The RGBA interface addresses pixels by absolute data-window coordinates; shift the base
    // in integer arithmetic (out-of-range pointer arithmetic would be undefined behaviour).
    const intptr_t shift =
        (intptr_t(dw.x0) + intptr_t(dw.y0) * dw.width) * intptr_t(sizeof(Imf::Rgba));
    file.setFrameBuffer(
        reinterpret_cast<Imf::Rgba*>(reinterpret_cast<intptr_t>(rgba.data()) - shift), 1,
        size_t(dw.width));
    file.readPixels(dw.y0, dw.y0 + dw.height - 1);
    std::vector<glm::vec3> data(rgba.size());
    for (size_t i = 0; i < rgba.size(); ++i)
        data[i] = glm::vec3(float(rgba[i].r), float(rgba[i].g), float(rgba[i].b));
    return data;
}

std::vector<glm::vec3> read_rgb_or_grey(Imf::InputFile& file, const std::filesystem::path& path,
                                        Window dw, const Imath::Box2i& data_box) {
    const Imf::ChannelList& channels = file.header().channels();
    const bool grey =
        !channels.findChannel("R") && !channels.findChannel("G") && !channels.findChannel("B");
    std::vector<glm::vec3> data(size_t(dw.width) * size_t(dw.height), glm::vec3(0.0f));
    Imf::FrameBuffer frame;
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) {
        const char* name = grey ? "Y" : names[c];
        const Imf::Channel* channel = channels.findChannel(name);
        // A missing R, G or B reads as 0 (OpenEXR fills absent slices).
        if (channel && (channel->xSampling != 1 || channel->ySampling != 1))
            fail(
                "{}: OpenEXR channel '{}' is subsampled ({}x{}); only full-resolution RGB or Y "
                "is supported",
                path.string(), name, channel->xSampling, channel->ySampling);
        frame.insert(name, Imf::Slice::Make(Imf::FLOAT, &data[0][c], data_box, sizeof(glm::vec3),
                                            sizeof(glm::vec3) * size_t(dw.width)));
        // With a grey file the single Y channel goes into R; copied to G, B below.
        if (grey) break;
    }
    file.setFrameBuffer(frame);
    file.readPixels(data_box.min.y, data_box.max.y);
    if (grey)
        for (glm::vec3& p : data) p = glm::vec3(p.x);
    return data;
}

uint32_t little_endian_32(const char* b) {
    return uint32_t(uint8_t(b[0])) | uint32_t(uint8_t(b[1])) << 8 | uint32_t(uint8_t(b[2])) << 16 |
           uint32_t(uint8_t(b[3])) << 24;
}

// The size OpenEXR 3.1 reads for a known attribute type of fixed layout
// (its TypedAttribute readers ignore the declared size), 0 for the others.
int fixed_attribute_size(const std::string& type) {
    static const std::pair<const char*, int> kSizes[] = {
        {"box2i", 16},      {"box2f", 16},   {"chromaticities", 32},
        {"compression", 1}, {"double", 8},   {"envmap", 1},
        {"float", 4},       {"int", 4},      {"keycode", 28},
        {"lineOrder", 1},   {"m33f", 36},    {"m33d", 72},
        {"m44f", 64},       {"m44d", 128},   {"rational", 8},
        {"tiledesc", 9},    {"timecode", 8}, {"v2i", 8},
        {"v2f", 8},         {"v2d", 16},     {"v3i", 12},
        {"v3f", 12},        {"v3d", 24},     {"deepImageState", 1},
    };
    for (const auto& [name, size] : kSizes)
        if (type == name) return size;
    return 0;
}

// Scanlines in one chunk of each compression (OpenEXR file layout,
// "Scan Lines"): OpenEXR's scanline reader allocates a buffer of that many
// uncompressed lines of the data window when it opens the file.
int64_t exr_lines_per_chunk(int compression) {
    switch (compression) {
        case 3:
        case 5:
            return 16;  // ZIP, PXR24
        case 4:
        case 6:
        case 7:
        case 8:
            return 32;  // PIZ, B44, B44A, DWAA
        case 9:
            return 256;  // DWAB
        default:
            return 1;  // none, RLE, ZIPS (and unknown: OpenEXR rejects)
    }
}

// OpenEXR's header reader allocates each attribute's value at the size the
// file declares before reading it (OpaqueAttribute::readValueFrom for types
// it does not know, PreviewImage for "preview"), so a 250-byte file declaring
// a 1.6 GB attribute made every read allocate 1.6 GB (found by the image
// fuzzer). The header is a list of (name\0, type\0, int32 size, value) ended
// by an empty name, one header per part for multi-part files (version flag
// 0x1000), the list ended by an empty header (OpenEXR file layout, "Header").
// This walks it as OpenEXR 3.1 does: a value of a fixed-size known type
// (box2i, v3f, ...) is read at that type's size whatever its declared size,
// a "chlist" entry by entry up to its empty name, a "preview" allocates
// width x height x 4 bytes; any other value is its declared size, allocated
// first. Every allocation must fit in what is left of the file. A structure
// this walk cannot follow is left to OpenEXR to report.
// The walk also checks each part's data window against the memory limit
// before OpenEXR sees it: opening a file allocates line buffers of the
// window's width (a chunk of lines, every channel), so a 405-byte file
// claiming a 33-million-pixel-wide window allocated a gigabyte before
// read_exr's own size check ran (found by the image fuzzer as a 35 s
// timeout under ASan, which fills freed blocks; fuzz/regressions/image/
// exr_data_window_33M_wide.exr).
void check_exr_attribute_sizes(const std::filesystem::path& path) {
    std::error_code ec;
    const uint64_t file_size = std::filesystem::file_size(path, ec);
    std::ifstream in(path, std::ios::binary);
    char head[8];
    if (ec || !in.read(head, 8)) return;
    const bool multipart = (little_endian_32(head + 4) & 0x1000) != 0;
    auto read_string = [&](std::string& s) {
        s.clear();
        for (char c; in.get(c);) {
            if (c == '\0') return true;
            s += c;
            if (s.size() > 255) return false;  // names and types are at most 255 bytes
        }
        return false;
    };
    auto left = [&] {
        const std::streamoff pos = in.tellg();
        return pos < 0 ? 0 : file_size - std::min(file_size, uint64_t(pos));
    };
    auto require_fits = [&](const std::string& name, const std::string& type, uint64_t bytes) {
        if (bytes > left())
            fail(
                "{}: cannot read OpenEXR file: header attribute '{}' of type '{}' declares {} "
                "bytes but only {} bytes of the file follow it",
                path.string(), name, type, bytes, left());
    };
    std::string name, type, channel;
    for (bool any = true; any;) {
        any = false;
        int64_t window_w = 0, window_h = 0, pixel_bytes = 0, lines = 1, tile_w = 0, tile_h = 0;
        while (read_string(name) && !name.empty()) {
            any = true;
            char word[16];
            if (!read_string(type) || !in.read(word, 4)) return;
            const auto size = static_cast<int32_t>(little_endian_32(word));
            if (size < 0) return;  // OpenEXR rejects it
            if (name == "dataWindow" && type == "box2i") {
                if (!in.read(word, 16)) return;
                auto side = [&](int lo, int hi) {
                    return int64_t(int32_t(little_endian_32(word + 4 * hi))) -
                           int64_t(int32_t(little_endian_32(word + 4 * lo))) + 1;
                };
                window_w = side(0, 2), window_h = side(1, 3);
            } else if (name == "tiles" && type == "tiledesc") {
                // A tiled file's buffers hold whole tiles instead of lines.
                if (!in.read(word, 9)) return;
                tile_w = little_endian_32(word), tile_h = little_endian_32(word + 4);
            } else if (name == "compression" && type == "compression") {
                if (!in.read(word, 1)) return;
                lines = exr_lines_per_chunk(uint8_t(word[0]));
            } else if (const int fixed = fixed_attribute_size(type); fixed > 0) {
                in.seekg(fixed, std::ios::cur);
            } else if (type == "chlist") {
                // Entries: name\0, then 16 bytes (type, pLinear, reserved, sampling).
                pixel_bytes = 0;
                while (read_string(channel) && !channel.empty()) {
                    if (!in.read(word, 16)) return;
                    pixel_bytes += little_endian_32(word) == 1 ? 2 : 4;  // HALF, else 32 bits
                }
                if (!in) return;
            } else if (type == "preview") {
                if (size < 8 || !in.read(word, 8)) return;
                require_fits(name, type,
                             uint64_t(little_endian_32(word)) * little_endian_32(word + 4) * 4);
                in.seekg(size - 8, std::ios::cur);
            } else {
                require_fits(name, type, uint64_t(size));
                in.seekg(size, std::ios::cur);
            }
        }
        if (window_w > 0 && window_h > 0) {
            // As read_exr requires once the file is open (12 + 20 bytes a
            // pixel), and OpenEXR's line buffers.
            require_image_memory(path, "OpenEXR data window", window_w, window_h, 20);
            const bool tiled = tile_w > 0 && tile_h > 0;
            const int64_t buffer_w = tiled ? tile_w : window_w, buffer_h = tiled ? tile_h : lines;
            require_memory({{fmt::format("OpenEXR {} buffer ({}x{} pixels, {} bytes a pixel)",
                                         tiled ? "tile" : "line", buffer_w, buffer_h, pixel_bytes),
                             uint64_t(buffer_w) * uint64_t(buffer_h) * uint64_t(pixel_bytes)}},
                           fmt::format("{}: opening the OpenEXR file", path.string()));
        }
        if (!in || !multipart) return;
    }
}

}  // namespace

Image read_exr(const std::filesystem::path& path) {
    check_exr_attribute_sizes(path);
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imf::ChannelList& channels = header.channels();
        const Imath::Box2i data_box = header.dataWindow();
        // Sizes in 64 bits: max - min + 1 overflows int for windows that
        // span the int range, which a header may claim.
        const Imath::Box2i display_box = header.displayWindow();
        auto side = [](int lo, int hi) { return int64_t(hi) - int64_t(lo) + 1; };
        const int64_t dw_w = side(data_box.min.x, data_box.max.x),
                      dw_h = side(data_box.min.y, data_box.max.y);
        const int64_t display_w = side(display_box.min.x, display_box.max.x),
                      display_h = side(display_box.min.y, display_box.max.y);
        if (dw_w <= 0 || dw_h <= 0 || display_w <= 0 || display_h <= 0)
            fail("{}: OpenEXR image has zero size (data window {}x{}, display window {}x{})",
                 path.string(), dw_w, dw_h, display_w, display_h);
        // The data window is read into its own buffer (12 bytes a pixel, 8
        // more for luminance/chroma files), then placed in the display window.
        require_image_memory(path, "OpenEXR display window", display_w, display_h, 0);
        require_image_memory(path, "OpenEXR data window", dw_w, dw_h, 20);
        const Window dw = window_of(data_box);
        const Window display = window_of(display_box);

        const bool has_rgb =
            channels.findChannel("R") || channels.findChannel("G") || channels.findChannel("B");
        const bool has_y = channels.findChannel("Y") != nullptr;
        const bool has_chroma = channels.findChannel("RY") || channels.findChannel("BY");
        std::vector<glm::vec3> data;
        if (has_rgb || (has_y && !has_chroma))
            data = read_rgb_or_grey(file, path, dw, data_box);
        else if (has_y && has_chroma)
            data = read_luminance_chroma(path, dw);
        else
            fail("{}: OpenEXR file has no R, G, B or Y channel (channels: {})", path.string(),
                 channel_names(channels));
        return place_in_display_window(data, dw, display);
    } catch (const Error&) {
        throw;
    } catch (const std::exception& e) {
        fail("{}: cannot read OpenEXR file: {}", path.string(), e.what());
    }
}

void write_exr_zip_float(const Image& image, const std::filesystem::path& file,
                         const std::filesystem::path& name) {
    try {
        Imf::Header header(image.width, image.height);
        header.compression() = Imf::ZIP_COMPRESSION;
        const char* names[3] = {"R", "G", "B"};
        Imf::FrameBuffer frame;
        // OutputFile only reads the pixels; the Slice API takes a non-const pointer.
        char* base = reinterpret_cast<char*>(const_cast<glm::vec3*>(image.pixels.data()));
        for (int c = 0; c < 3; ++c) {
            header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
            frame.insert(names[c],
                         Imf::Slice(Imf::FLOAT, base + c * sizeof(float), sizeof(glm::vec3),
                                    sizeof(glm::vec3) * size_t(image.width)));
        }
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(frame);
        out.writePixels(image.height);
    } catch (const std::exception& e) {
        fail("{}: cannot write OpenEXR file: {}", name.string(), e.what());
    }
}

}  // namespace glintlab::image_formats
