// The precompiled header of every test executable (sextant_test_pch in tests/CMakeLists.txt):
// GoogleTest, Eigen and the standard and core headers most test files include. Parsing them once
// instead of in each of the ~120 test files saves about a third of each file's compile time.
// Every test file still includes what it uses; this header only makes those includes cheap.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sextant/core/error.hpp"
#include "sextant/core/pose.hpp"
#include "sextant/core/rng.hpp"
#include "sextant/core/units.hpp"
