# Generated spectral tables: the RGB-to-spectrum coefficient tables of Jakob and Hanika 2019,
# one per standard colour space, optimised at build time by tools/rgb2spec_gen.cpp (see
# spectral/README.md). The generator is a host program built from the spectral sources it
# needs (CIE data, named illuminants); its binary output is assembled into the spectral module.

set(CAUSTICA_RGB2SPEC_RESOLUTION 64 CACHE STRING
    "Grid resolution of the RGB-to-spectrum tables (pbrt-v4 uses 64)")

find_package(Threads REQUIRED)
add_executable(caustica_rgb2spec_gen
  ${CMAKE_CURRENT_SOURCE_DIR}/tools/rgb2spec_gen.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/spectral/camera_sensor_data.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/spectral/cie.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/spectral/cie_data.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/spectral/ior.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/spectral/metal_data.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/spectral/named_spectra.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/spectral/spectrum.cpp)
target_include_directories(caustica_rgb2spec_gen PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}
                           ${CMAKE_CURRENT_SOURCE_DIR}/src)
target_link_libraries(caustica_rgb2spec_gen PRIVATE Threads::Threads)
# The fit's inner loop is a reduction over wavelengths: let it vectorise (`omp simd` only, no
# OpenMP runtime), with sqrt free of errno side effects.
if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
  target_compile_options(caustica_rgb2spec_gen PRIVATE -fopenmp-simd -fno-math-errno)
endif()

set(_rgb2spec_dir ${CMAKE_BINARY_DIR}/generated/spectral)
set(_rgb2spec_source ${_rgb2spec_dir}/rgb_to_spectrum_tables.cpp)
set(_rgb2spec_tables)
foreach(space srgb aces2065-1 rec2020 dci-p3)  # as in spectral/standard_color_spaces.h
  list(APPEND _rgb2spec_tables ${_rgb2spec_dir}/rgb2spec_${space}.bin)
endforeach()

add_custom_command(
  OUTPUT ${_rgb2spec_source} ${_rgb2spec_tables}
  COMMAND caustica_rgb2spec_gen ${_rgb2spec_dir} ${CAUSTICA_RGB2SPEC_RESOLUTION}
  DEPENDS caustica_rgb2spec_gen
  COMMENT "Optimising RGB-to-spectrum tables (resolution ${CAUSTICA_RGB2SPEC_RESOLUTION})"
  VERBATIM)
# The source only .incbin's the tables: recompile it whenever they change.
set_source_files_properties(${_rgb2spec_source} PROPERTIES GENERATED TRUE
                            OBJECT_DEPENDS "${_rgb2spec_tables}")

set(CAUSTICA_GENERATED_SOURCES ${_rgb2spec_source})
add_custom_target(caustica_generated_tables DEPENDS ${_rgb2spec_source} ${_rgb2spec_tables})
