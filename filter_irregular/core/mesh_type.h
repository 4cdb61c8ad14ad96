// filter_irregular: MeshLab's mesh type CMeshO, from the MeshLab generation being built
// (FI_MESHLAB_API is 2020 or 2025; set by filter_irregular/CMakeLists.txt).
#pragma once
#if FI_MESHLAB_API == 2025
#include <common/ml_document/cmesh.h>
#elif FI_MESHLAB_API == 2020
#include <common/ml_mesh_type.h>
#else
#error "FI_MESHLAB_API must be 2020 or 2025"
#endif
