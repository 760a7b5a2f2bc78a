# Every dependency comes from a Debian 12 package (see scripts/setup) and is
# used through its CMake imported target, so its headers are SYSTEM includes
# and its warnings never fail our -Werror build.
find_package(Threads REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenCV 4.6 REQUIRED COMPONENTS core imgproc imgcodecs videoio features2d calib3d ml)
find_package(Ceres 2.1 REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(spdlog REQUIRED)
find_package(fmt REQUIRED)
# JSON reports and checkpoints (nlohmann-json3-dev).
find_package(nlohmann_json 3 REQUIRED)
# Optional: `mpirun -np N facadeslam optimise` spreads fitness evaluations
# over ranks (libopenmpi-dev); without it optimise runs threaded only.
find_package(MPI COMPONENTS CXX QUIET)
# The .fsmodel forest files are zlib-compressed (semantics/forest/zlib_codec.hpp).
find_package(ZLIB REQUIRED)
if(FACADESLAM_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(FACADESLAM_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# OpenCV's config exports plain variables rather than one imported target;
# wrap them so that its headers are SYSTEM includes like everything else.
if(NOT TARGET facadeslam::opencv)
  add_library(facadeslam_opencv INTERFACE)
  add_library(facadeslam::opencv ALIAS facadeslam_opencv)
  target_include_directories(facadeslam_opencv SYSTEM INTERFACE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(facadeslam_opencv INTERFACE ${OpenCV_LIBS})
endif()
