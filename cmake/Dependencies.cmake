# Every dependency comes from Debian's packages (scripts/setup.sh installs them).
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Threads REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(fmt REQUIRED)
find_package(TBB REQUIRED)
find_package(CLI11 REQUIRED)
# JSON of the result rows, provenance and metrics (pipeline/json.hpp).
find_package(nlohmann_json 3.2 REQUIRED)
find_package(Ceres REQUIRED)

# Recordings (recordings/): ROS 2 bags' sqlite3 files, and the chunk compressions of bags and MCAP files.
find_package(SQLite3 REQUIRED)
find_package(BZip2 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(SEXTANT_LZ4 REQUIRED IMPORTED_TARGET liblz4)
pkg_check_modules(SEXTANT_ZSTD REQUIRED IMPORTED_TARGET libzstd)

# GeographicLib ships its Find module outside CMake's default search path on Debian.
list(APPEND CMAKE_MODULE_PATH /usr/share/cmake/geographiclib)
find_package(GeographicLib REQUIRED)

# Debian's PCL pulls in VTK, whose config needs MPI's C component found first.
find_package(MPI COMPONENTS C QUIET)
find_package(PCL REQUIRED COMPONENTS common io kdtree search registration filters sample_consensus surface)
# PCL stays at the edges: one interface target that the few adapting files link privately.
add_library(sextant_pcl INTERFACE)
target_include_directories(sextant_pcl SYSTEM INTERFACE ${PCL_INCLUDE_DIRS})
target_link_libraries(sextant_pcl INTERFACE ${PCL_LIBRARIES})
target_compile_definitions(sextant_pcl INTERFACE ${PCL_DEFINITIONS})

if(SEXTANT_BUILD_TESTS)
  find_package(GTest REQUIRED)
  include(GoogleTest)
endif()
if(SEXTANT_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
  # Only bench/bench_kd_tree.cpp, which measures ICP's k-d tree against it.
  find_package(nanoflann REQUIRED)
endif()
