// Precompiled header of the output and command layers (report, batch, the
// framedyn program): the numerical libraries' header (numerics.h) and the JSON
// and YAML libraries their sources include, parsed once per target instead of
// once per source file (FRAMEDYN_PCH in CMakeLists.txt). It declares nothing of
// framedyn's; every source still includes what it uses.
#pragma once
#include "numerics.h"
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>
