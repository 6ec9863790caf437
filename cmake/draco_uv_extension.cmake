# Included by Draco's own CMakeLists.txt through the build hook of
# patches/0003, before Draco defines any source list or target: puts the
# draco-uv tree on Draco's include path and adds our sources to Draco's
# encoder and decoder source lists, so that libdraco, the tools and Draco's
# unit tests all build with the extension.

get_filename_component(draco_uv_root "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
# The prediction scheme families (prediction_schemes/<family>/) and the rest
# of the extension (draco_ext/<capability>/), both included from the root.
set(draco_uv_schemes "${draco_uv_root}/prediction_schemes")
set(draco_uv_ext "${draco_uv_root}/draco_ext")

list(APPEND draco_include_paths "${draco_uv_root}")
# The Laplacian decoder's sparse Cholesky factorises on two threads; the
# weighted scheme computes its stencils' frames ahead on a second thread.
find_package(Threads REQUIRED)
link_libraries(Threads::Threads)
# The Laplacian texture coordinate coder needs Eigen, which Draco itself puts
# on the include path only for its transcoder.
if(DRACO_UV_LAPLACIAN AND DRACO_EIGEN_PATH)
  list(APPEND draco_include_paths "${DRACO_EIGEN_PATH}")
endif()

list(
  APPEND draco_compression_attributes_pred_schemes_dec_sources
         "${draco_uv_ext}/hooks/prediction_scheme_decoders.h"
         "${draco_uv_ext}/hooks/prediction_scheme_ids.h"
         "${draco_uv_ext}/common/uv_bitstream_guard.h"
         "${draco_uv_ext}/common/uv_prediction_ids.h"
         "${draco_uv_ext}/common/fixed_point.h"
         "${draco_uv_ext}/common/threads.h"
         "${draco_uv_schemes}/weighted/uv_lookahead.h"
         "${draco_uv_schemes}/weighted/uv_processing_order.h"
         "${draco_uv_schemes}/weighted/mesh_prediction_scheme_tex_coords_weighted_decoder.h"
         "${draco_uv_schemes}/weighted/mesh_prediction_scheme_tex_coords_weighted_predictor.h"
         "${draco_uv_schemes}/weighted/mesh_prediction_scheme_tex_coords_weighted_shared.h"
         "${draco_uv_schemes}/weighted/uv_stencil_geometry.h"
         "${draco_uv_schemes}/tangent/geometric_tangent_coder.h"
         "${draco_uv_schemes}/tangent/geometric_tangent_predictor.h"
         "${draco_uv_schemes}/tangent/geometric_tangent_settings.h"
         "${draco_uv_schemes}/tangent/mesh_prediction_scheme_geometric_tangent_decoder.h"
         "${draco_uv_schemes}/tangent/mesh_prediction_scheme_geometric_tangent_shared.h"
         "${draco_uv_schemes}/tangent/tangent_geometry.h")

list(
  APPEND draco_compression_attributes_pred_schemes_enc_sources
         "${draco_uv_ext}/hooks/prediction_scheme_encoders.h"
         "${draco_uv_schemes}/weighted/mesh_prediction_scheme_tex_coords_weighted_encoder.h"
         "${draco_uv_schemes}/tangent/mesh_prediction_scheme_geometric_tangent_encoder.h")

# Object libraries with Draco's include paths (the prediction scheme lists
# above are header-only and compiled without them).
#
# Which list a source joins matters for Draco's Emscripten build, whose
# draco_decoder target links only the decoder lists (*_dec_*, *_decode_*)
# and draco_encoder only the encoder lists (*_enc_*, *_encode_*), both the
# common ones; libdraco links them all. Sources that both sides use (coders
# with an encoding and a decoding half, models, topology, the Laplacian
# system the encoder also solves) go to the common list
# draco_compression_entropy_sources.
list(
  APPEND draco_compression_decode_sources
         "${draco_uv_ext}/hooks/edgebreaker_decoder.h"
         "${draco_uv_ext}/seams/mesh_edgebreaker_traversal_uv_seam_decoder.h"
         "${draco_uv_ext}/seams/uv_seam_edgebreaker_decoder.cc")
list(
  APPEND draco_compression_entropy_sources
         "${draco_uv_ext}/common/rans_token_table.cc"
         "${draco_uv_ext}/common/rans_token_table.h"
         "${draco_uv_ext}/common/uv_residual_coder.cc"
         "${draco_uv_ext}/common/uv_residual_coder.h"
         "${draco_uv_ext}/seams/uv_seam_coder.cc"
         "${draco_uv_ext}/seams/uv_seam_coder.h"
         "${draco_uv_ext}/seams/uv_seam_edgebreaker.cc"
         "${draco_uv_ext}/seams/uv_seam_edgebreaker.h"
         "${draco_uv_ext}/seams/uv_seam_range_coder.cc"
         "${draco_uv_ext}/seams/uv_seam_range_coder.h")

# Seen by tests/CMakeLists.txt, outside Draco's directory scope.
set(DRACO_UV_DENSE_FRONT_AVX2 OFF CACHE INTERNAL "")
# The Laplacian texture coordinate coder (encoder and decoder) and its
# solver; lossless-only builds (DRACO_UV_LAPLACIAN=OFF) leave them and Eigen
# out. The web decoder with the Laplacian part on demand
# (DRACO_UV_LAPLACIAN_ON_DEMAND, see the top-level CMakeLists.txt) has the
# scheme but not the solver, which the part (draco_decoder_laplacian)
# links; its encoder keeps everything.
set(draco_uv_laplacian_decoder_headers
    "${draco_uv_schemes}/laplacian/mesh_prediction_scheme_tex_coords_laplacian_decoder.h"
    "${draco_uv_schemes}/laplacian/mesh_prediction_scheme_tex_coords_laplacian_shared.h"
    "${draco_uv_schemes}/laplacian/uv_laplacian_decode.h"
    "${draco_uv_schemes}/laplacian/uv_laplacian_mesh.h")
if(DRACO_UV_LAPLACIAN AND DRACO_UV_LAPLACIAN_ON_DEMAND)
  set(draco_uv_laplacian_list draco_compression_encode_sources)
  list(APPEND draco_compression_decode_sources
       ${draco_uv_laplacian_decoder_headers}
       "${draco_uv_ext}/web/uv_laplacian_on_demand.cc")
else()
  set(draco_uv_laplacian_list draco_compression_entropy_sources)
endif()
if(DRACO_UV_LAPLACIAN)
  list(
    APPEND ${draco_uv_laplacian_list}
           ${draco_uv_laplacian_decoder_headers}
           "${draco_uv_schemes}/laplacian/mesh_prediction_scheme_tex_coords_laplacian_encoder.h"
           "${draco_uv_schemes}/laplacian/uv_laplacian_coder.cc"
           "${draco_uv_schemes}/laplacian/uv_laplacian_coder.h"
           "${draco_uv_schemes}/laplacian/uv_laplacian_operator.cc"
           "${draco_uv_schemes}/laplacian/uv_laplacian_operator.h"
           "${draco_uv_schemes}/laplacian/uv_laplacian_system.cc"
           "${draco_uv_schemes}/laplacian/uv_laplacian_system.h"
           "${draco_uv_ext}/linalg/sparse_cholesky.cc"
           "${draco_uv_ext}/linalg/sparse_cholesky.h"
           "${draco_uv_ext}/linalg/dense_front.cc"
           "${draco_uv_ext}/linalg/dense_front.h"
           "${draco_uv_ext}/linalg/dense_front_impl.h"
           "${draco_uv_ext}/linalg/dense_front_portable.cc"
           "${draco_uv_ext}/linalg/matrix_graph.h")

  # On x86-64, the Laplacian decoder's dense kernels also in an AVX2 and FMA
  # build, chosen at run time on CPUs that have both (dense_front.h).
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag("-mavx2 -mfma" DRACO_UV_COMPILER_HAS_AVX2_FMA)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$"
     AND CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang"
     AND DRACO_UV_COMPILER_HAS_AVX2_FMA)
    list(APPEND draco_compression_entropy_sources
         "${draco_uv_ext}/linalg/dense_front_avx2.cc")
    set_source_files_properties("${draco_uv_ext}/linalg/dense_front_avx2.cc"
                                PROPERTIES COMPILE_OPTIONS "-mavx2;-mfma")
    set_source_files_properties("${draco_uv_ext}/linalg/dense_front.cc"
                                PROPERTIES COMPILE_DEFINITIONS
                                           DRACO_UV_DENSE_FRONT_AVX2)
    set(DRACO_UV_DENSE_FRONT_AVX2 ON CACHE INTERNAL "")
  endif()
endif()

list(
  APPEND draco_compression_encode_sources
         "${draco_uv_ext}/hooks/compression_options.h"
         "${draco_uv_ext}/hooks/gltf.h"
         "${draco_uv_ext}/hooks/tool_flags.h"
         "${draco_uv_ext}/common/uv_rmse.cc"
         "${draco_uv_ext}/common/uv_rmse.h"
         "${draco_uv_schemes}/laplacian/uv_laplacian_settings.cc"
         "${draco_uv_schemes}/laplacian/uv_laplacian_settings.h"
         "${draco_uv_ext}/options/draco_uv_flags.cc"
         "${draco_uv_ext}/options/draco_uv_flags.h"
         "${draco_uv_ext}/options/uv_compression_options.cc"
         "${draco_uv_ext}/options/uv_compression_options.h"
         "${draco_uv_ext}/options/uv_configure.cc"
         "${draco_uv_ext}/options/uv_configure.h"
         "${draco_uv_ext}/options/uv_encode_settings.cc"
         "${draco_uv_ext}/options/uv_encode_settings.h"
         "${draco_uv_ext}/options/uv_error_target.cc"
         "${draco_uv_ext}/options/uv_error_target.h"
         "${draco_uv_ext}/gltf/uv_gltf.cc"
         "${draco_uv_ext}/gltf/uv_gltf.h"
         "${draco_uv_ext}/gltf/uv_gltf_extension.h"
         "${draco_uv_ext}/options/uv_laplacian_options.cc"
         "${draco_uv_ext}/options/uv_laplacian_options.h"
         "${draco_uv_ext}/options/uv_prediction_options.cc"
         "${draco_uv_ext}/options/uv_prediction_options.h"
         "${draco_uv_ext}/hooks/edgebreaker_encoder.h"
         "${draco_uv_ext}/seams/mesh_edgebreaker_traversal_uv_seam_encoder.h"
         "${draco_uv_ext}/seams/uv_seam_edgebreaker_encoder.cc"
         "${draco_uv_ext}/options/tangent_compression_options.cc"
         "${draco_uv_ext}/options/tangent_compression_options.h"
         "${draco_uv_ext}/options/tangent_prediction_options.cc"
         "${draco_uv_ext}/options/tangent_prediction_options.h"
         "${draco_uv_ext}/options/trial_encoder.cc"
         "${draco_uv_ext}/options/trial_encoder.h"
         "${draco_uv_ext}/options/uv_seam_options.cc"
         "${draco_uv_ext}/options/uv_seam_options.h"
         "${draco_uv_ext}/hooks/web_encoder.h"
         "${draco_uv_ext}/web/uv_web_encoder.cc"
         "${draco_uv_ext}/web/uv_web_encoder.h")
if(EMSCRIPTEN)
  # The encoder's cold code, run a few times per encode (flag parsing,
  # option checks, the choices' drivers, the JS encoder's setup): compiled
  # for size.
  set(draco_uv_cold_sources
      "${draco_uv_ext}/options/draco_uv_flags.cc"
      "${draco_uv_ext}/options/uv_compression_options.cc"
      "${draco_uv_ext}/options/uv_configure.cc"
      "${draco_uv_ext}/options/uv_encode_settings.cc"
      "${draco_uv_ext}/options/uv_error_target.cc"
      "${draco_uv_ext}/options/uv_laplacian_options.cc"
      "${draco_uv_ext}/options/uv_prediction_options.cc"
      "${draco_uv_ext}/options/tangent_compression_options.cc"
      "${draco_uv_ext}/options/tangent_prediction_options.cc"
      "${draco_uv_ext}/options/trial_encoder.cc"
      "${draco_uv_ext}/options/uv_seam_options.cc"
      "${draco_uv_ext}/web/uv_web_encoder.cc")
  set_source_files_properties(${draco_uv_cold_sources}
                              PROPERTIES COMPILE_OPTIONS "-Oz")
endif()
