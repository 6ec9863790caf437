# The web decoder with its Laplacian part on demand (DRACO_UV_LAPLACIAN_ON_DEMAND,
# Emscripten only), included by the top-level CMakeLists.txt after Draco's
# targets exist:
#  * draco_decoder gets web/laplacian_on_demand.js, which loads the part when
#    a file needs it (its Laplacian scheme calls it through
#    draco_ext/web/uv_laplacian_on_demand.cc), and
#    web/laplacian_script_url.js, which notes the script's URL;
#  * draco_decoder_laplacian builds the part, draco_decoder_laplacian.wasm: a
#    standalone module (no JS glue, its own memory, capped at 2 GB like the
#    decoder's) exporting malloc, free and draco_uv_laplacian_decode
#    (draco_ext/web/uv_laplacian_part.cc), with the Laplacian decoder, its
#    solver and the Draco code they use, built with the decoder's flags.
# Both link only what the decode reaches; the part's encoder halves (in the
# same sources) are left out by the linker.
em_link_post_js(draco_decoder "${CMAKE_CURRENT_SOURCE_DIR}/web/laplacian_on_demand.js")
em_add_tracked_link_flag(draco_decoder "--extern-pre-js"
                         "${CMAKE_CURRENT_SOURCE_DIR}/web/laplacian_script_url.js")

set(draco_uv_src "${DRACO_UV_PATCHED_SOURCE_DIR}/src/draco")
add_executable(
  draco_decoder_laplacian
  draco_ext/web/uv_laplacian_part.cc
  draco_ext/common/rans_token_table.cc
  draco_ext/common/uv_residual_coder.cc
  draco_ext/linalg/dense_front.cc
  draco_ext/linalg/dense_front_portable.cc
  draco_ext/linalg/sparse_cholesky.cc
  prediction_schemes/laplacian/uv_laplacian_coder.cc
  prediction_schemes/laplacian/uv_laplacian_operator.cc
  prediction_schemes/laplacian/uv_laplacian_settings.cc
  prediction_schemes/laplacian/uv_laplacian_system.cc
  "${draco_uv_src}/compression/bit_coders/direct_bit_decoder.cc"
  "${draco_uv_src}/core/decoder_buffer.cc"
  "${draco_uv_src}/core/encoder_buffer.cc")
target_include_directories(
  draco_decoder_laplacian
  PRIVATE "${CMAKE_CURRENT_SOURCE_DIR}" "${DRACO_UV_PATCHED_SOURCE_DIR}/src"
          "${CMAKE_BINARY_DIR}" "${DRACO_EIGEN_PATH}")
set_target_properties(
  draco_decoder_laplacian
  PROPERTIES SUFFIX ".wasm" RUNTIME_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/draco")
# Smaller than the decoder's -O3 and dlmalloc at the same speed: -O2,
# emmalloc and no RTTI take the part from 35.5 to 31.9 KB gzip, and decode
# within a few percent of -O3 (benchmarks/web.md, "The Laplacian part on
# demand").
target_compile_options(draco_decoder_laplacian PRIVATE -O2 -fno-rtti)
target_link_options(
  draco_decoder_laplacian PRIVATE
  "-O2" "-sMALLOC=emmalloc" "--no-entry" "-sSTANDALONE_WASM" "-sFILESYSTEM=0"
  "-sEXPORTED_FUNCTIONS=_malloc,_free,_draco_uv_laplacian_decode"
  "-sALLOW_MEMORY_GROWTH=1" "-sMAXIMUM_MEMORY=2147483648"
  "-sABORTING_MALLOC=0")
