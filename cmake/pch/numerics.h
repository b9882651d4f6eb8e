// Precompiled header of the numerical libraries (fem, rigid, coupling): the
// standard, Eigen and fmt headers most of their sources include, directly or
// through framedyn's own headers, parsed once per library instead of once per
// source file (FRAMEDYN_PCH in CMakeLists.txt; docs/benchmarks.md, "The test
// suite's build time"). It declares nothing of framedyn's: every source still
// includes what it uses, and builds without it (FRAMEDYN_PCH=OFF, ccache builds).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <fmt/format.h>
