# Every third-party library vesica uses, found once here so that the stage
# folders only name imported targets. All of them come from Debian packages
# (see the Makefile's DEBIAN_PACKAGES).

# What the libraries link: shared with the installed CMake package (find_package(vesica)).
include(vesicaDependencies)

# ITK_USE_FILE registers the IO factories in the translation units that read images; it is
# compiled into vesica_segment and vesica_surface, so consumers of the package need none.
include(${ITK_USE_FILE})

# Only for the tests and benchmarks.
find_package(GTest REQUIRED)
find_package(benchmark QUIET)
