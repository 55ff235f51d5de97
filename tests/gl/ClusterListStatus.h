// The size of shaders/lib/cluster_list_status.glsl's ClusterListStatus, which the tests of the
// list passes bind and read back (GlobalLightOrderTest.cpp, LongListTilesTest.cpp).
#pragma once

#include <cstddef>

namespace manylights::test {

inline constexpr std::size_t kClusterListStatusUints = 16;

}  // namespace manylights::test
