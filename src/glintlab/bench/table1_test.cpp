// `bench --set`: every row's scene document takes the edits before loading.
#include <gtest/gtest.h>

#include "glintlab/bench/table1.h"
#include "glintlab/core/error.h"
#include "glintlab/loader/scene_loader.h"

namespace glintlab {
namespace {

TEST(Table1, SetsEditEveryRowsDocumentBeforeLoading) {
    Table1Options o;
    o.width = 32, o.height = 18;
    o.sets = {"/materials/0/roughness=0.45",
              R"(/materials/0/wang2020={"scale_count":"particles"})"};
    const nlohmann::json j = table1_scene_document(o, "SPHERE", "wang2020", 12.0f);
    EXPECT_EQ(j["materials"][0]["roughness"], 0.45);
    EXPECT_EQ(j["materials"][0]["wang2020"]["scale_count"], "particles");
    const Scene scene = parse_scene(j, "test:bench");
    EXPECT_FLOAT_EQ(scene.materials[0].glint.alpha_x, 0.45f);
    // The strict loader still checks the edited document.
    o.sets = {R"(/materials/0/wang2020={"scale_count":"all"})"};
    EXPECT_THROW(parse_scene(table1_scene_document(o, "SPHERE", "wang2020", 12.0f), "test:bench"),
                 Error);
    o.sets = {"/no/such/parent=1"};
    EXPECT_THROW(table1_scene_document(o, "SPHERE", "wang2020", 12.0f), Error);
}

}  // namespace
}  // namespace glintlab
