// glTF materials as scene-format materials (gltf_materials.h): the keys a
// file's pbrMetallicRoughness, normalTexture, KHR_texture_transform,
// samplers and KHR_materials_ior become, what is named as unread, and what a
// material override keeps from the file.
#include "glintlab/scene/gltf_materials.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "glintlab/core/error.h"

namespace glintlab {
namespace {

using nlohmann::json;

const std::vector<std::string> kImages = {"/assets/colour.png", "<f.glb image 1>",
                                          "/assets/normal.png"};

json document(const json& material) {
    return {{"materials", {material}},
            {"textures",
             {{{"source", 0}, {"sampler", 0}}, {{"source", 1}}, {{"source", 2}, {"sampler", 1}}}},
            {"samplers", {{{"wrapS", 33071}, {"wrapT", 33071}}, {{"wrapS", 10497}}}}};
}

json textured_paint() {
    return {{"name", "Paint"},
            {"pbrMetallicRoughness",
             {{"baseColorFactor", {0.5, 1.0, 0.25, 1.0}},
              {"baseColorTexture",
               {{"index", 0},
                {"extensions",
                 {{"KHR_texture_transform",
                   {{"scale", {2.0, 3.0}},
                    {"offset", {0.5, 0.0}},
                    {"rotation", 1.5707963267948966}}}}}}},
              {"metallicFactor", 0.8},
              {"roughnessFactor", 0.5},
              {"metallicRoughnessTexture", {{"index", 1}}}}},
            {"normalTexture", {{"index", 2}, {"scale", 0.7}}}};
}

TEST(GltfMaterials, MetallicRoughnessFactorsAndTexturesBecomeTextureForms) {
    const GltfMaterial m = translate_gltf_material(document(textured_paint()), 0, kImages, "f.glb");
    EXPECT_EQ(m.name, "Paint");
    EXPECT_TRUE(m.unread.empty());
    EXPECT_EQ(m.uv_set, 0);
    EXPECT_EQ(m.block["type"], "metallic_roughness");
    // The base colour: the factor as a scale a channel, the transform's
    // rotation in degrees, the sampler's wrap.
    const json& base = m.block["base_color"];
    EXPECT_EQ(base["texture"], "/assets/colour.png");
    EXPECT_EQ(base["scale"], json({0.5, 1.0, 0.25}));
    EXPECT_EQ(base["uv_transform"]["scale"], json({2.0, 3.0}));
    EXPECT_EQ(base["uv_transform"]["offset"], json({0.5, 0.0}));
    EXPECT_NEAR(base["uv_transform"]["rotation_deg"].get<double>(), 90.0, 1e-9);
    EXPECT_EQ(base["wrap"], "clamp");
    // Metallic in B, roughness in G squared to α, each with its factor.
    EXPECT_EQ(m.block["metallic"],
              json({{"texture", "<f.glb image 1>"}, {"channel", "b"}, {"scale", 0.8}}));
    EXPECT_EQ(
        m.block["roughness"],
        json({{"texture", "<f.glb image 1>"}, {"channel", "g"}, {"scale", 0.5}, {"power", 2}}));
    EXPECT_EQ(m.block["normal_map"], json({{"texture", "/assets/normal.png"}, {"scale", 0.7}}));
    EXPECT_EQ(m.images, std::vector<int>({0, 1, 2}));
    EXPECT_TRUE(m.metallic);

    // Factors alone: α = roughness², glTF's defaults where a factor is absent.
    const GltfMaterial plain = translate_gltf_material(
        document({{"pbrMetallicRoughness", {{"roughnessFactor", 0.3}, {"metallicFactor", 0.0}}},
                  {"extensions", {{"KHR_materials_ior", {{"ior", 1.33}}}}}}),
        0, kImages, "f.glb");
    EXPECT_EQ(plain.name, "material 0");
    EXPECT_EQ(plain.block["base_color"], json({1.0, 1.0, 1.0}));
    EXPECT_NEAR(plain.block["roughness"].get<double>(), 0.09, 1e-12);
    EXPECT_EQ(plain.block["metallic"], 0.0);
    EXPECT_EQ(plain.block["eta"], 1.33);
    EXPECT_FALSE(plain.metallic);
    // glTF's default material (§3.9.6).
    const GltfMaterial fallback = translate_gltf_material(document(plain.block), -1, kImages, "f");
    EXPECT_EQ(fallback.name, "default");
    EXPECT_EQ(fallback.block["metallic"], 1.0);
    EXPECT_EQ(fallback.block["roughness"], 1.0);
}

TEST(GltfMaterials, WhatIsNotReadIsNamedAndTwoUvSetsAreAnError) {
    json m = {
        {"name", "Odd"},
        {"emissiveFactor", {1.0, 0.0, 0.0}},
        {"alphaMode", "BLEND"},
        {"extensions",
         {{"KHR_materials_clearcoat", json::object()}, {"KHR_materials_ior", {{"ior", 1.0}}}}},
        {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 2}}}}}};
    json doc = document(m);
    doc["samplers"][1]["wrapT"] = 33648;
    const GltfMaterial odd = translate_gltf_material(doc, 0, kImages, "f.glb");
    std::string unread;
    for (const std::string& u : odd.unread) unread += u + "|";
    EXPECT_NE(unread.find("emission"), std::string::npos) << unread;
    EXPECT_NE(unread.find("alphaMode BLEND"), std::string::npos) << unread;
    EXPECT_NE(unread.find("KHR_materials_clearcoat"), std::string::npos) << unread;
    EXPECT_NE(unread.find("ior 1 (outside (1, 4]"), std::string::npos) << unread;
    EXPECT_EQ(unread.find("wrap"), std::string::npos) << unread;  // s and t apart: read
    EXPECT_EQ(odd.block["base_color"]["wrap"], json::array({"repeat", "mirror"}));
    doc["samplers"][1]["wrapS"] = 1234;
    std::string bad_wrap;
    for (const std::string& u : translate_gltf_material(doc, 0, kImages, "f.glb").unread)
        bad_wrap += u + "|";
    EXPECT_NE(bad_wrap.find("sampler 1 wrapS 1234 is not a glTF wrap mode"), std::string::npos)
        << bad_wrap;
    // Filters other than the footprint's, and a sampler the file lacks, are named.
    doc["samplers"][1] = {{"magFilter", 9728}, {"minFilter", 9728}};
    std::string nearest;
    for (const std::string& u : translate_gltf_material(doc, 0, kImages, "f.glb").unread)
        nearest += u + "|";
    EXPECT_NE(nearest.find("sampler 1 asks for nearest filtering"), std::string::npos) << nearest;
    doc["textures"][2]["sampler"] = 7;
    std::string missing;
    for (const std::string& u : translate_gltf_material(doc, 0, kImages, "f.glb").unread)
        missing += u + "|";
    EXPECT_NE(missing.find("sampler 7 is not in the file's samplers"), std::string::npos)
        << missing;

    json two_sets = textured_paint();
    two_sets["normalTexture"]["texCoord"] = 1;
    try {
        translate_gltf_material(document(two_sets), 0, kImages, "f.glb");
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("f.glb: material \"Paint\" reads its textures through TEXCOORD_0 "
                               "and TEXCOORD_1 (normalTexture)"),
                  std::string::npos)
            << message;
    }
    // A texture without a PNG/JPEG source: named, and the factor is used.
    json doc_no_source = document(textured_paint());
    doc_no_source["textures"][0].erase("source");
    const GltfMaterial no_source = translate_gltf_material(doc_no_source, 0, kImages, "f.glb");
    EXPECT_EQ(no_source.block["base_color"], json({0.5, 1.0, 0.25}));
    ASSERT_EQ(no_source.unread.size(), 1u);
    EXPECT_NE(no_source.unread[0].find("baseColorTexture (texture 0 has no PNG/JPEG source"),
              std::string::npos);
}

TEST(GltfMaterials, AGlintOverrideKeepsTheFileInputsItDoesNotSet) {
    const GltfMaterial paint =
        translate_gltf_material(document(textured_paint()), 0, kImages, "f.glb");
    std::vector<std::string> notes;
    const json glint = apply_material_override(
        paint, {{"type", "glint"}, {"model", "deliot2023"}, {"log_density", 14}}, &notes);
    EXPECT_EQ(glint["roughness"], paint.block["roughness"]);
    EXPECT_EQ(glint["normal_map"], paint.block["normal_map"]);
    EXPECT_EQ(glint["color"], paint.block["base_color"]);  // the metallic side
    EXPECT_FALSE(glint.contains("base_albedo"));
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("metallic map is not carried"), std::string::npos) << notes[0];

    // The dielectric side: the base colour lies under a dielectric coat of
    // the file's IOR; keys the override sets win.
    json dielectric_doc = document(textured_paint());
    dielectric_doc["materials"][0]["pbrMetallicRoughness"].erase("metallicRoughnessTexture");
    dielectric_doc["materials"][0]["pbrMetallicRoughness"]["metallicFactor"] = 0.0;
    dielectric_doc["materials"][0]["extensions"] = {{"KHR_materials_ior", {{"ior", 1.6}}}};
    const GltfMaterial coat = translate_gltf_material(dielectric_doc, 0, kImages, "f.glb");
    notes.clear();
    const json flakes = apply_material_override(
        coat, {{"type", "glint"}, {"model", "zirr2016"}, {"roughness", 0.2}}, &notes);
    EXPECT_TRUE(notes.empty());
    EXPECT_EQ(flakes["roughness"], 0.2);
    EXPECT_EQ(flakes["base_albedo"], coat.block["base_color"]);
    EXPECT_EQ(flakes["fresnel"], json({{"type", "dielectric"}, {"eta", 1.6}}));
    EXPECT_FALSE(flakes.contains("color"));
    // A file roughness of 0 (a mirror) is as smooth as a glint allows.
    json mirror_doc = dielectric_doc;
    mirror_doc["materials"][0]["pbrMetallicRoughness"]["roughnessFactor"] = 0.0;
    const GltfMaterial mirror = translate_gltf_material(mirror_doc, 0, kImages, "f.glb");
    EXPECT_EQ(apply_material_override(mirror, {{"type", "glint"}}, &notes)["roughness"], 1e-3);

    // Without a type: the file's material with the override's keys changed.
    const json tweaked = apply_material_override(paint, {{"metallic", 0.0}}, &notes);
    EXPECT_EQ(tweaked["type"], "metallic_roughness");
    EXPECT_EQ(tweaked["metallic"], 0.0);
    EXPECT_EQ(tweaked["roughness"], paint.block["roughness"]);
    // Diffuse takes the base colour as its albedo and the normal map.
    const json diffuse = apply_material_override(paint, {{"type", "diffuse"}}, &notes);
    EXPECT_EQ(diffuse["albedo"], paint.block["base_color"]);
    EXPECT_EQ(diffuse["normal_map"], paint.block["normal_map"]);
    EXPECT_FALSE(diffuse.contains("roughness"));
}

}  // namespace
}  // namespace glintlab
