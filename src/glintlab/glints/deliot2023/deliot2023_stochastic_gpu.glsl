// GPU glue of deliot2023's option "stochastic_grid": one of the 4 grids per
// pixel and frame, chosen by its weight (deliot2023.glsl
// deliot2023_ndf_stochastic), for renderers with temporal accumulation.
#ifndef GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_STOCHASTIC_GPU_GLSL
#define GLINTLAB_GLINTS_DELIOT2023_DELIOT2023_STOCHASTIC_GPU_GLSL

#define GLINTLAB_DELIOT2023_STOCHASTIC_GRID 1
#include "glintlab/glints/deliot2023/deliot2023_gpu.glsl"

#endif
