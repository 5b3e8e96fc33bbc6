#include "glintlab/gl/uniform_cache.h"

#include <epoxy/gl.h>

namespace glintlab::gl {

int UniformCache::location(unsigned program, const char* name) {
    auto key = std::make_pair(program, std::string(name));
    const auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    const int loc = glGetUniformLocation(program, name);
    cache_.emplace(std::move(key), loc);
    return loc;
}

void UniformCache::forget(unsigned program) {
    for (auto it = cache_.begin(); it != cache_.end();)
        it = it->first.first == program ? cache_.erase(it) : std::next(it);
}

}  // namespace glintlab::gl
