# Every dependency comes from a Debian 12 package (scripts/setup.sh installs them); nothing is downloaded.
find_package(Threads REQUIRED)
find_package(glm REQUIRED)                      # libglm-dev
find_package(ZLIB REQUIRED)                     # zlib1g-dev: CRC-32 of .vxm files
find_package(nlohmann_json 3.10 REQUIRED)       # nlohmann-json3-dev: CLI --json output, project manifests
find_package(CLI11 REQUIRED)                    # libcli11-dev: command-line parsing
find_package(PkgConfig REQUIRED)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)   # libstb-dev: PNG writing (stbi_write_png lives in libstb.so)
# libteem-dev: NRRD volumes (the reference implementation of the format). Its CMake config names the build machine's
# paths, so the library and header are found directly.
find_library(TEEM_LIBRARY teem REQUIRED)
find_path(TEEM_INCLUDE_DIR teem/nrrd.h REQUIRED)
add_library(Teem::teem UNKNOWN IMPORTED)
set_target_properties(Teem::teem PROPERTIES IMPORTED_LOCATION "${TEEM_LIBRARY}"
                                            INTERFACE_INCLUDE_DIRECTORIES "${TEEM_INCLUDE_DIR}")

find_package(assimp 5 REQUIRED)  # libassimp-dev: mesh formats other than STL (OBJ, PLY, 3MF, glTF, OFF)
# libminizip-dev (assimp's own zip library): 3MF packages are re-read with its 64-bit API (docs/dependencies.md).
pkg_check_modules(MINIZIP REQUIRED IMPORTED_TARGET minizip)
find_package(EXPAT REQUIRED)  # libexpat1-dev: the length unit of a 3MF model (assimp does not report it)
find_package(embree 3 REQUIRED)  # libembree-dev: ray thickness, rays cast against the mesh

# libocct-*-dev (Open CASCADE 7.6): STEP and IGES. Debian's config checks every component's targets, so all the
# installed ones are named; only the data-exchange, healing and meshing libraries are linked (OCCT::occt). Its
# targets carry no include directory; an imported target's are system headers (OCCT's warn under -Wpedantic).
find_package(OpenCASCADE REQUIRED COMPONENTS FoundationClasses ModelingData ModelingAlgorithms Visualization
                                             ApplicationFramework DataExchange)
if(OpenCASCADE_VERSION VERSION_LESS 7.6)
  message(FATAL_ERROR "voxmod needs Open CASCADE 7.6 or newer (found ${OpenCASCADE_VERSION})")
endif()
add_library(OCCT::occt INTERFACE IMPORTED)
set_target_properties(OCCT::occt PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${OpenCASCADE_INCLUDE_DIR}")
target_link_libraries(OCCT::occt INTERFACE TKSTEP TKSTEPBase TKIGES TKXSBase TKShHealing TKMesh TKTopAlgo TKGeomAlgo TKBRep
                                           TKGeomBase TKG3d TKG2d TKMath TKernel)
# Tests build their parts with OCCT's primitives (BRepPrimAPI) and write them with STEPControl_Writer.
add_library(OCCT::primitives INTERFACE IMPORTED)
target_link_libraries(OCCT::primitives INTERFACE OCCT::occt TKPrim TKBO)

# Volume export (docs/dependencies.md). libvtk9-dev: VTK image data (.vti) through VTK's own XML writer, and its base64
# for the report's embedded pictures (io/html.cpp); only the modules those need.
find_package(VTK REQUIRED COMPONENTS CommonCore CommonDataModel IOCore IOXML)
# libopenvdb-dev: OpenVDB volumes (.vdb). Debian's FindOpenVDB.cmake requires Boost's iostreams CMake package, which
# libopenvdb-dev does not depend on (libopenvdb.so links it itself), so the library and headers are found directly.
# OpenVDB's headers use TBB and Imath's half (libtbb-dev, libimath-dev: dependencies of libopenvdb-dev).
find_package(TBB REQUIRED)
find_package(Imath REQUIRED)
find_library(OPENVDB_LIBRARY openvdb REQUIRED)
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
add_library(OpenVDB::openvdb UNKNOWN IMPORTED)
set_target_properties(OpenVDB::openvdb PROPERTIES IMPORTED_LOCATION "${OPENVDB_LIBRARY}"
                                                  INTERFACE_INCLUDE_DIRECTORIES "${OPENVDB_INCLUDE_DIR}"
                                                  INTERFACE_LINK_LIBRARIES "TBB::tbb;Imath::Imath")

# libopenmpi-dev (optional): voxmod batch over MPI ranks (mpirun, srun). Without it batch runs on one machine only.
option(VOXMOD_WITH_MPI "Build voxmod batch with MPI when an MPI implementation is found" ON)
if(VOXMOD_WITH_MPI)
  set(MPI_CXX_SKIP_MPICXX ON)  # the C API only: no deprecated C++ bindings
  find_package(MPI COMPONENTS CXX)
endif()

set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)   # libopengl-dev, libegl-dev
find_package(glfw3 3.3 REQUIRED)                      # libglfw3-dev
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)   # libimgui-dev (holds the GLFW + OpenGL3 backends)

if(VOXMOD_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(VOXMOD_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
