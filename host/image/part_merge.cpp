#include "part_merge.h"

#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "exr_header_check.h"
#include "render_options.h"

namespace vkrt {

namespace {

struct Part {
    int index = 0, count = 0;
    glm::ivec2 rows{0};
    std::string render;  // vkrt:render: the options every part of one render shares
};

// A part is an OpenEXR file (the format that keeps vkrt's attributes): checked from its first
// bytes, so that a PNG claiming 40000 x 40000 pixels, a device such as /dev/zero or a folder is
// refused before any decoder runs.
void checkIsExrFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw std::runtime_error(path + ": not a regular file (merge reads the .exr parts vkrt --part writes)");
    if (!isExrFile(path))
        throw std::runtime_error(path + ": not an OpenEXR file (merge reads the .exr parts vkrt --part I/N -o part.exr writes)");
}

Part parsePart(const std::string& path, const ImageAttributes& a) {
    const auto get = [&](const char* name) {
        const auto found = a.find(name);
        if (found == a.end())
            throw std::runtime_error(path + ": not a part of a render (no " + name + "; write parts with vkrt --part I/N -o part.exr)");
        return found->second;
    };
    Part p;
    char extra = 0;
    if (std::sscanf(get("vkrt:part").c_str(), "%d/%d%c", &p.index, &p.count, &extra) != 2 || p.count < 1 || p.index < 1 ||
        p.index > p.count)
        throw std::runtime_error(path + ": vkrt:part '" + get("vkrt:part") + "' is not I/N");
    if (std::sscanf(get("vkrt:rows").c_str(), "%d %d%c", &p.rows.x, &p.rows.y, &extra) != 2)
        throw std::runtime_error(path + ": vkrt:rows '" + get("vkrt:rows") + "' is not two row numbers");
    p.render = get("vkrt:render");
    return p;
}

}  // namespace

Image mergeParts(const std::vector<std::string>& paths) {
    if (paths.empty()) throw std::runtime_error("merge: no parts given");
    Image merged;
    std::string render, first;
    std::map<int, std::string> seen;  // part index -> its file
    int count = 0;
    for (const std::string& path : paths) {
        checkIsExrFile(path);
        ImageAttributes attributes;
        const Image image = readImage(path, &attributes);
        const Part part = parsePart(path, attributes);
        const std::string& thisRender = part.render;
        // Every part has a row at least: a count above the height is a damaged or forged file (it
        // would also make the list of missing parts as long as the count).
        if (part.count > image.height)
            throw std::runtime_error(path + ": vkrt:part " + std::to_string(part.index) + "/" + std::to_string(part.count) +
                                     " of a " + std::to_string(image.height) + "-row image (a part has at least one row)");
        if (const std::size_t bad = countNonFinite(image); bad > 0)
            throw std::runtime_error(path + ": " + std::to_string(bad) + " pixel(s) are NaN or Inf, which a render never writes");
        if (first.empty()) {
            first = path;
            render = thisRender;
            count = part.count;
            merged = Image(image.width, image.height);
        } else if (thisRender != render || part.count != count) {
            throw std::runtime_error(path + ": a part of another render than " + first + " (" + std::to_string(part.index) + "/" +
                                     std::to_string(part.count) + ": " + thisRender + "; " + first + ": " + render + ")");
        }
        if (image.width != merged.width || image.height != merged.height)
            throw std::runtime_error(path + ": " + std::to_string(image.width) + "x" + std::to_string(image.height) + ", not " +
                                     std::to_string(merged.width) + "x" + std::to_string(merged.height) + " as " + first);
        if (part.rows != partRows(image.height, part.index, part.count))
            throw std::runtime_error(path + ": rows " + std::to_string(part.rows.x) + ".." + std::to_string(part.rows.y) +
                                     " are not those of part " + std::to_string(part.index) + "/" + std::to_string(part.count));
        if (const auto [it, added] = seen.emplace(part.index, path); !added)
            throw std::runtime_error(path + ": part " + std::to_string(part.index) + "/" + std::to_string(count) +
                                     " is given twice (also " + it->second + ")");
        for (int j = part.rows.x; j < part.rows.y; ++j)
            for (int i = 0; i < image.width; ++i) merged.at(i, j) = image.at(i, j);
    }
    std::string missing;
    int missingCount = 0;
    for (int k = 1; k <= count; ++k)
        if (!seen.count(k) && ++missingCount <= 20) missing += (missing.empty() ? "" : ", ") + std::to_string(k);
    if (missingCount > 20) missing += " and " + std::to_string(missingCount - 20) + " more";
    if (missingCount > 0)
        throw std::runtime_error("merge: part(s) " + missing + " of " + std::to_string(count) + " missing (" +
                                 std::to_string(seen.size()) + " given)");
    return merged;
}

}  // namespace vkrt
