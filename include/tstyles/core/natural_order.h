// Names in the order people number files: "t2.tif" before "t10.tif" (digit runs compare as
// numbers), and the pattern a numbered series' names share.
#pragma once

#include <string>
#include <string_view>

namespace tstyles {

bool naturalLess(const std::string& a, const std::string& b);

// The name with each run of digits made one '#': "flow_0012.vtk" -> "flow_#.vtk". Files of one
// numbered series share it.
std::string numberPattern(std::string_view name);

}  // namespace tstyles
