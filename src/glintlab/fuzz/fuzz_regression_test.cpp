// The fuzzing entry points in the ordinary suite (no clang needed): every
// input that once crashed a fuzzer (fuzz/regressions/<target>/) is replayed
// through the same function the fuzzer calls, the seed corpus loads, and the
// scene dictionary covers every key of the model descriptors and the seeds.
#include "glintlab/fuzz/fuzz_entries.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glintlab/glints/glint_model_descriptor.h"
#include "glintlab/glints/registry.h"

namespace glintlab::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = GLINTLAB_SOURCE_DIR;

std::string read_bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

Outcome run_file(Target target, const fs::path& path, std::string* error = nullptr) {
    const std::string bytes = read_bytes(path);
    return run(target, reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), error);
}

// A scratch directory of this test and process (ctest runs tests in parallel).
fs::path scratch(const std::string& name) {
    const fs::path p =
        fs::temp_directory_path() / ("glintlab_fuzz_test_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(p);
    return p;
}

TEST(FuzzRegression, ReplaysEveryCrashingInput) {
    size_t total = 0;
    for (Target target : kTargets) {
        const fs::path dir = kSource / "fuzz" / "regressions" / std::string(target_name(target));
        if (!fs::is_directory(dir)) continue;  // no input of this target yet
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (!entry.is_regular_file() || entry.path().filename().string().starts_with("."))
                continue;
            SCOPED_TRACE(entry.path().string());
            // Loads or is rejected with glintlab::Error; anything else
            // (another exception, an InvariantViolation) fails here, and a
            // crash, leak or undefined behaviour fails the sanitized suite.
            EXPECT_NO_THROW(run_file(target, entry.path()));
            ++total;
        }
    }
    EXPECT_GT(total, 0u) << "the regression corpus is empty";
}

// Every seed loads: the seeds reach deep into the loaders only if they are
// valid, and they double as a test of the in-memory loaders
// (load_gltf_bytes, load_obj_text) and of the assets scenes reference.
TEST(FuzzSeeds, EverySeedLoads) {
    for (Target target : kTargets) {
        const fs::path dir = scratch(std::string(target_name(target)));
        const size_t n = write_seeds(target, dir, kSource);
        EXPECT_GE(n, 2u);
        size_t seen = 0;
        for (const auto& entry : fs::directory_iterator(dir)) {
            SCOPED_TRACE(entry.path().string());
            std::string error;
            EXPECT_EQ(run_file(target, entry.path(), &error), Outcome::Accepted) << error;
            ++seen;
        }
        EXPECT_EQ(seen, n);
        fs::remove_all(dir);
    }
}

TEST(FuzzEntries, MalformedInputsAreRejectedNotThrown) {
    const std::string garbage = "{\"film\": [1, 2, \x01 glTF v/1";
    const auto* data = reinterpret_cast<const uint8_t*>(garbage.data());
    for (Target target : kTargets) {
        SCOPED_TRACE(std::string(target_name(target)));
        EXPECT_EQ(run(target, data, garbage.size()), Outcome::Rejected);
        EXPECT_EQ(run(target, data, 0), Outcome::Rejected);
    }
}

// The tokens of fuzz/scene.dict (libFuzzer's format: one quoted string per
// line, backslash escapes), without their outer quotes.
std::set<std::string> dictionary_tokens() {
    std::ifstream in(kSource / "fuzz" / "scene.dict");
    std::set<std::string> tokens;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::string token;
        for (size_t i = 1; i + 1 < line.size(); ++i) {
            if (line[i] == '\\' && i + 2 < line.size()) ++i;
            token += line[i];
        }
        tokens.insert(token);
    }
    return tokens;
}

void collect_keys(const nlohmann::json& value, std::set<std::string>& keys) {
    if (value.is_object()) {
        for (const auto& [k, v] : value.items()) {
            keys.insert(k);
            collect_keys(v, keys);
        }
    } else if (value.is_array()) {
        for (const auto& v : value) collect_keys(v, keys);
    }
}

// fuzz/make_dict.py generates the dictionary from `glintlab info --json` and
// the seeds; this fails when either gained a key since (rerun the script).
TEST(FuzzDictionary, CoversDescriptorsAndSeeds) {
    const std::set<std::string> tokens = dictionary_tokens();
    ASSERT_GT(tokens.size(), 50u);
    auto quoted = [](const std::string& s) { return "\"" + s + "\""; };
    for (const GlintModelDescriptor& model : glint_models()) {
        EXPECT_TRUE(tokens.contains(quoted(std::string(model.name)))) << model.name;
        for (const GlintParam& p : model.params) {
            EXPECT_TRUE(tokens.contains(quoted(p.key))) << model.name << "." << p.key;
            for (const std::string& c : p.choices)
                EXPECT_TRUE(tokens.contains(quoted(c))) << model.name << "." << p.key << " " << c;
        }
        for (const GlintExtraKey& e : model.extra_keys)
            EXPECT_TRUE(tokens.contains(quoted(e.key))) << model.name << "." << e.key;
    }
    const fs::path dir = scratch("dict");
    write_seeds(Target::Scene, dir, kSource);
    std::set<std::string> keys;
    for (const auto& entry : fs::directory_iterator(dir))
        collect_keys(nlohmann::json::parse(read_bytes(entry.path())), keys);
    fs::remove_all(dir);
    EXPECT_GT(keys.size(), 50u);
    for (const std::string& k : keys) EXPECT_TRUE(tokens.contains(quoted(k))) << k;
}

}  // namespace
}  // namespace glintlab::fuzz
