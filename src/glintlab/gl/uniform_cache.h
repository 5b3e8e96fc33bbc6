// Uniform locations of linked programs, looked up once per (program, name).
#pragma once

#include <map>
#include <string>
#include <utility>

namespace glintlab::gl {

class UniformCache {
  public:
    // -1 when the program has no active uniform `name` (GL ignores writes to -1).
    int location(unsigned program, const char* name);
    void forget(unsigned program);

  private:
    std::map<std::pair<unsigned, std::string>, int, std::less<>> cache_;
};

}  // namespace glintlab::gl
