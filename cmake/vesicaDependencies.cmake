# Every third-party library the vesica libraries link, found once, with the small
# imported targets (vesica_itk, vesica_vtk, vesica_gmsh, vesica_suitesparse, vesica_mumps)
# that stand for the libraries Debian ships without a usable CMake config.
#
# Included twice over: by the build (cmake/Dependencies.cmake) and, installed beside
# vesicaConfig.cmake, by every project that calls find_package(vesica). The installed
# static libraries name these targets in their link interface, so a consumer must define
# them exactly as the build did; one file for both keeps the two from drifting apart.
# All of them come from Debian packages (see the Makefile's DEBIAN_PACKAGES).

include(CMakeFindDependencyMacro)

# find_package in the build, find_dependency (which marks vesica as not found instead of
# stopping the consumer's configure) inside find_package(vesica). Decided once, here: the
# dependencies' own configs change CMAKE_FIND_PACKAGE_NAME while they load.
if(CMAKE_FIND_PACKAGE_NAME STREQUAL "vesica")
  set(_vesica_as_package TRUE)
else()
  set(_vesica_as_package FALSE)
endif()
macro(vesica_find_dependency)
  if(_vesica_as_package)
    find_dependency(${ARGN})
  else()
    find_package(${ARGN} REQUIRED)
  endif()
endmacro()

vesica_find_dependency(Eigen3 3.3 NO_MODULE)
vesica_find_dependency(nlohmann_json 3)
vesica_find_dependency(fmt)
vesica_find_dependency(spdlog)
vesica_find_dependency(yaml-cpp)
vesica_find_dependency(OpenSSL)  # SHA-256 content hashes for manifests
vesica_find_dependency(Threads)
vesica_find_dependency(ZLIB)  # checks gzip outputs whole (core/src/OutputCheck.cpp)
vesica_find_dependency(OpenMP COMPONENTS CXX)  # thread counts of CHOLMOD and the BLAS
find_package(CLI11 QUIET CONFIG)

# CLI11 is header-only; Debian ships a config on some releases only.
if(NOT TARGET CLI11::CLI11)
  find_path(CLI11_INCLUDE_DIR CLI/CLI.hpp REQUIRED)
  add_library(CLI11::CLI11 INTERFACE IMPORTED)
  target_include_directories(CLI11::CLI11 INTERFACE ${CLI11_INCLUDE_DIR})
endif()

# yaml-cpp's Debian config exports the plain "yaml-cpp" target.
if(NOT TARGET yaml-cpp::yaml-cpp)
  add_library(yaml-cpp::yaml-cpp INTERFACE IMPORTED)
  target_link_libraries(yaml-cpp::yaml-cpp INTERFACE yaml-cpp)
endif()

# ITK: images, DICOM (GDCM), filters. Its config runs an HDF5 check written in C.
if(NOT CMAKE_C_COMPILER_LOADED)
  enable_language(C)
endif()
vesica_find_dependency(ITK COMPONENTS
  ITKCommon ITKIOImageBase ITKIOGDCM ITKIONIFTI ITKIONRRD ITKIOMeta ITKGDCM
  ITKThresholding ITKConnectedComponents ITKBinaryMathematicalMorphology
  ITKMathematicalMorphology ITKRegionGrowing ITKLabelMap ITKSmoothing
  ITKAnisotropicSmoothing ITKLevelSets ITKImageIntensity ITKImageGrid
  ITKDistanceMap ITKImageFilterBase ITKImageFunction ITKImageStatistics
  ITKLabelVoting ITKImageFeature)
if(NOT TARGET vesica_itk)
  add_library(vesica_itk INTERFACE IMPORTED)
  target_link_libraries(vesica_itk INTERFACE ${ITK_LIBRARIES})
  target_include_directories(vesica_itk INTERFACE ${ITK_INCLUDE_DIRS})
endif()

# VTK: isosurfaces, smoothing, VTK file formats, off-screen rendering.
vesica_find_dependency(VTK COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel FiltersCore FiltersGeneral
  FiltersGeometry FiltersModeling FiltersSources FiltersExtraction IOXML IOGeometry
  IOLegacy IOPLY ImagingCore ImagingGeneral ImagingMorphological RenderingCore
  RenderingOpenGL2 RenderingFreeType RenderingAnnotation InteractionStyle IOImage)
if(NOT TARGET vesica_vtk)
  add_library(vesica_vtk INTERFACE IMPORTED)
  target_link_libraries(vesica_vtk INTERFACE ${VTK_LIBRARIES})
endif()

# CGAL: remeshing, self-intersection tests, geometry predicates.
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
vesica_find_dependency(CGAL)

# assimp: foreign surface formats (OBJ and friends).
vesica_find_dependency(assimp)
if(NOT TARGET assimp::assimp)
  add_library(assimp::assimp INTERFACE IMPORTED)
  target_link_libraries(assimp::assimp INTERFACE ${ASSIMP_LIBRARIES})
endif()

# gmsh: tetrahedral meshing through its C++ API (Debian ships no CMake config).
if(NOT TARGET vesica_gmsh)
  find_library(GMSH_LIBRARY NAMES gmsh REQUIRED)
  find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
  add_library(vesica_gmsh INTERFACE IMPORTED)
  target_link_libraries(vesica_gmsh INTERFACE ${GMSH_LIBRARY})
  target_include_directories(vesica_gmsh INTERFACE ${GMSH_INCLUDE_DIR})
endif()

# SuiteSparse: CHOLMOD and UMFPACK behind Eigen's wrappers.
if(NOT TARGET vesica_suitesparse)
  find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
  find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
  find_library(UMFPACK_LIBRARY umfpack REQUIRED)
  find_library(AMD_LIBRARY amd REQUIRED)
  find_library(COLAMD_LIBRARY colamd REQUIRED)
  find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
  add_library(vesica_suitesparse INTERFACE IMPORTED)
  target_include_directories(vesica_suitesparse INTERFACE ${SUITESPARSE_INCLUDE_DIR})
  target_link_libraries(vesica_suitesparse INTERFACE ${UMFPACK_LIBRARY} ${CHOLMOD_LIBRARY}
    ${AMD_LIBRARY} ${COLAMD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY} Eigen3::Eigen)
endif()

# MUMPS (sequential build): sparse LDLᵀ of the symmetric indefinite wall tangent past
# the pressure limit point (simulate/src/solver/SymmetricIndefiniteLdlt.cpp). No CMake config.
if(NOT TARGET vesica_mumps)
  find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
  find_library(DMUMPS_LIBRARY dmumps_seq REQUIRED)
  find_library(MUMPS_COMMON_LIBRARY mumps_common_seq REQUIRED)
  add_library(vesica_mumps INTERFACE IMPORTED)
  target_include_directories(vesica_mumps INTERFACE ${MUMPS_INCLUDE_DIR})
  target_link_libraries(vesica_mumps INTERFACE ${DMUMPS_LIBRARY} ${MUMPS_COMMON_LIBRARY})
endif()
