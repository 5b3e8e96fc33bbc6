// Parameters of the jakob2014 glint model (its block "jakob2014": {...} of a
// glint material; ranges and defaults justified in docs/MODELS.md).
#pragma once

namespace glintlab {

struct Jakob2014Params {
    // Query cone radius γ around the outgoing direction (002 §3.1), degrees.
    // The paper's scenes use 0.5°-6° (Table 1); the authors' default is 1°.
    float gamma_deg = 1.0f;
    // Per-particle Dirichlet areas per colour channel (002 §3.5, Fig. 8).
    bool chromatic = false;
    // ε of the adaptive error criterion (002 Eq. 10); the paper uses 0.1.
    float error_threshold = 0.1f;
    // Deepest node of the 4-D hierarchy (authors' maxDepth 20).
    int max_depth = 20;
    // E[A(query)] of 002 Eq. 11: the expected uv area of one query (the
    // statistic the paper collects in a short prior run; see MODELS.md).
    double query_area = 1e-6;
};

}  // namespace glintlab
