// The test executables' precompiled header (tests/CMakeLists.txt,
// FRAMEDYN_TEST_PCH): third-party and standard headers that most test files
// include, directly or through framedyn's headers, compiled once per build.
// Only headers that do not change with framedyn's code: a change here rebuilds
// every test. Test files still include what they use.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
