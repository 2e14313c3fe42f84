# Every third-party library vesica uses, found once here so that the stage
# folders only name imported targets. All of them come from Debian packages
# (see the Makefile's DEBIAN_PACKAGES).

find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 QUIET CONFIG)
find_package(fmt REQUIRED)
find_package(spdlog REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(OpenSSL REQUIRED)  # SHA-256 content hashes for manifests
find_package(Threads REQUIRED)
find_package(ZLIB REQUIRED)  # checks gzip outputs whole (core/src/OutputCheck.cpp)

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

# ITK: images, DICOM (GDCM), filters. ITK_USE_FILE registers the IO factories.
find_package(ITK REQUIRED COMPONENTS
  ITKCommon ITKIOImageBase ITKIOGDCM ITKIONIFTI ITKIONRRD ITKIOMeta ITKGDCM
  ITKThresholding ITKConnectedComponents ITKBinaryMathematicalMorphology
  ITKMathematicalMorphology ITKRegionGrowing ITKLabelMap ITKSmoothing
  ITKAnisotropicSmoothing ITKLevelSets ITKImageIntensity ITKImageGrid
  ITKDistanceMap ITKImageFilterBase ITKImageFunction ITKImageStatistics
  ITKLabelVoting ITKImageFeature)
include(${ITK_USE_FILE})
add_library(vesica_itk INTERFACE)
target_link_libraries(vesica_itk INTERFACE ${ITK_LIBRARIES})
target_include_directories(vesica_itk SYSTEM INTERFACE ${ITK_INCLUDE_DIRS})

# VTK: isosurfaces, smoothing, VTK file formats, off-screen rendering.
find_package(VTK REQUIRED COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel FiltersCore FiltersGeneral
  FiltersGeometry FiltersModeling FiltersSources FiltersExtraction IOXML IOGeometry
  IOLegacy IOPLY ImagingCore ImagingGeneral ImagingMorphological RenderingCore
  RenderingOpenGL2 RenderingFreeType RenderingAnnotation InteractionStyle IOImage)
add_library(vesica_vtk INTERFACE)
target_link_libraries(vesica_vtk INTERFACE ${VTK_LIBRARIES})

# CGAL: remeshing, self-intersection tests, geometry predicates.
set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
find_package(CGAL REQUIRED)

# assimp: foreign surface formats (OBJ and friends).
find_package(assimp REQUIRED)
if(NOT TARGET assimp::assimp)
  add_library(assimp::assimp INTERFACE IMPORTED)
  target_link_libraries(assimp::assimp INTERFACE ${ASSIMP_LIBRARIES})
endif()

# gmsh: tetrahedral meshing through its C++ API (Debian ships no CMake config).
find_library(GMSH_LIBRARY NAMES gmsh REQUIRED)
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
add_library(vesica_gmsh INTERFACE)
target_link_libraries(vesica_gmsh INTERFACE ${GMSH_LIBRARY})
target_include_directories(vesica_gmsh SYSTEM INTERFACE ${GMSH_INCLUDE_DIR})

# SuiteSparse: CHOLMOD and UMFPACK behind Eigen's wrappers.
find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
find_library(UMFPACK_LIBRARY umfpack REQUIRED)
find_library(AMD_LIBRARY amd REQUIRED)
find_library(COLAMD_LIBRARY colamd REQUIRED)
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
add_library(vesica_suitesparse INTERFACE)
target_include_directories(vesica_suitesparse SYSTEM INTERFACE ${SUITESPARSE_INCLUDE_DIR})
target_link_libraries(vesica_suitesparse INTERFACE ${UMFPACK_LIBRARY} ${CHOLMOD_LIBRARY}
  ${AMD_LIBRARY} ${COLAMD_LIBRARY} ${SUITESPARSECONFIG_LIBRARY} Eigen3::Eigen)

# MUMPS (sequential build): sparse LDLᵀ of the symmetric indefinite wall tangent past
# the pressure limit point (simulate/src/SymmetricIndefiniteLdlt.cpp). No CMake config.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_library(DMUMPS_LIBRARY dmumps_seq REQUIRED)
find_library(MUMPS_COMMON_LIBRARY mumps_common_seq REQUIRED)
add_library(vesica_mumps INTERFACE)
target_include_directories(vesica_mumps SYSTEM INTERFACE ${MUMPS_INCLUDE_DIR})
target_link_libraries(vesica_mumps INTERFACE ${DMUMPS_LIBRARY} ${MUMPS_COMMON_LIBRARY})

find_package(GTest REQUIRED)
find_package(benchmark QUIET)
