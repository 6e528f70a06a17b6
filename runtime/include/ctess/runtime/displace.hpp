// Displacement in the runtime (docs/algorithm.md §8): height maps sampled bilinearly at LOD 0
// (displace/height_map.hpp: HeightMap, sample_bilinear) and watertight displacement of the mesh pipeline's
// output along one direction per position, with gradient normals and factors grown by the height bound
// (displace/displace.hpp: Displacement, welded_directions; set PipelineOptions::displacement). Decoding
// height images from files is the models room's (models::load_height_map).
#pragma once

#include "displace/displace.hpp"
#include "displace/height_map.hpp"
