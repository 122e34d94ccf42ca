# Finds every Debian package pdrt builds against. Each failure names the package
# and the script that installs it, before any compilation starts.
set(PDRT_DEPS_HINT "run: bash third_party/install-deps.sh (as root on Debian 12)")

macro(pdrt_require pkg debian_pkg)
  find_package(${pkg} ${ARGN} QUIET)
  if(NOT ${pkg}_FOUND)
    message(FATAL_ERROR "pdrt: missing dependency ${pkg} (Debian package ${debian_pkg}); ${PDRT_DEPS_HINT}")
  endif()
endmacro()

pdrt_require(embree libembree-dev 3)
# Debian 12's Imath config (pulled in by OpenImageIO's) lists Imath::PyImath_Python3_11, whose
# library is in the separate python3-imath package, and says so on every configure in a
# message that reads like an error. Find Imath first with STATUS messages muted: its targets
# are then defined, so OpenImageIO's find_dependency(Imath) does not run that check again.
# Warnings and errors still show (they are above STATUS).
set(_pdrt_log_level "${CMAKE_MESSAGE_LOG_LEVEL}")
set(CMAKE_MESSAGE_LOG_LEVEL NOTICE)
find_package(Imath CONFIG QUIET)
set(CMAKE_MESSAGE_LOG_LEVEL "${_pdrt_log_level}")
pdrt_require(OpenImageIO libopenimageio-dev CONFIG)
# Debian's OpenImageIO config lists include directories of optional packages (OpenCV)
# that need not be installed; drop the ones that do not exist.
foreach(_oiio_target OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${_oiio_target})
    get_target_property(_dirs ${_oiio_target} INTERFACE_INCLUDE_DIRECTORIES)
    if(_dirs)
      set(_kept "")
      foreach(_d ${_dirs})
        if(EXISTS "${_d}" OR _d MATCHES "^\\$<")
          list(APPEND _kept "${_d}")
        endif()
      endforeach()
      set_target_properties(${_oiio_target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_kept}")
    endif()
  endif()
endforeach()
pdrt_require(tinyobjloader libtinyobjloader-dev CONFIG)
pdrt_require(assimp libassimp-dev CONFIG)
pdrt_require(TBB libtbb-dev CONFIG)
# Open MPI (distributed renders, docs/distributed.md); mpirun itself is in openmpi-bin.
find_package(MPI QUIET COMPONENTS CXX)
if(NOT MPI_CXX_FOUND)
  message(FATAL_ERROR "pdrt: missing dependency MPI (Debian packages libopenmpi-dev openmpi-bin); ${PDRT_DEPS_HINT}")
endif()
# OpenSubdiv (pbrt's loopsubdiv): Debian 12's OpenSubdivConfig.cmake names static libraries
# the package does not ship and fails, so the header and the CPU library are found directly.
find_path(OSD_INCLUDE_DIR opensubdiv/far/topologyRefinerFactory.h)
find_library(OSD_CPU_LIBRARY osdCPU)
if(NOT OSD_INCLUDE_DIR OR NOT OSD_CPU_LIBRARY)
  message(FATAL_ERROR "pdrt: missing dependency OpenSubdiv (Debian package libosd-dev); ${PDRT_DEPS_HINT}")
endif()
add_library(pdrt_opensubdiv INTERFACE)
target_include_directories(pdrt_opensubdiv SYSTEM INTERFACE ${OSD_INCLUDE_DIR})
target_link_libraries(pdrt_opensubdiv INTERFACE ${OSD_CPU_LIBRARY})
add_library(pdrt::opensubdiv ALIAS pdrt_opensubdiv)
pdrt_require(nlohmann_json nlohmann-json3-dev CONFIG)
pdrt_require(CLI11 libcli11-dev CONFIG)
pdrt_require(Threads build-essential)

# FFTW ships pkg-config files only.
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(FFTW3 QUIET IMPORTED_TARGET fftw3)
endif()
if(NOT FFTW3_FOUND)
  message(FATAL_ERROR "pdrt: missing dependency fftw3 (Debian package libfftw3-dev, needs pkg-config); ${PDRT_DEPS_HINT}")
endif()
add_library(pdrt::fftw3 ALIAS PkgConfig::FFTW3)

# pcg-cpp is header-only without a CMake package.
find_path(PCG_INCLUDE_DIR pcg_random.hpp)
if(NOT PCG_INCLUDE_DIR)
  message(FATAL_ERROR "pdrt: missing dependency pcg-cpp (Debian package libpcg-cpp-dev); ${PDRT_DEPS_HINT}")
endif()
add_library(pdrt_pcg INTERFACE)
target_include_directories(pdrt_pcg SYSTEM INTERFACE ${PCG_INCLUDE_DIR})
add_library(pdrt::pcg ALIAS pdrt_pcg)

if(PDRT_BUILD_TESTS)
  pdrt_require(GTest libgtest-dev)
endif()
if(PDRT_BUILD_BENCH)
  pdrt_require(benchmark libbenchmark-dev CONFIG)
endif()

find_package(Python3 COMPONENTS Interpreter QUIET)
if(NOT Python3_FOUND)
  message(FATAL_ERROR "pdrt: missing python3 (Debian packages python3 python3-matplotlib, used for plots); ${PDRT_DEPS_HINT}")
endif()
