# Prepares the Draco source tree that the build uses: Debian's draco
# 1.5.5+dfsg-2 (fetched by scripts/fetch-draco-source.sh) or the user's own
# checkout given as -DDRACO_SOURCE_DIR=<path>, copied into the build folder
# with patches/*.patch applied. The user's checkout is never modified.
#
# Applying is idempotent: a stamp records the source folder and the hash of
# every patch; a configure with the same stamp keeps the patched copy, a
# changed patch set or source folder makes a fresh copy.

set(DRACO_SOURCE_DIR "" CACHE PATH
    "Draco source checkout (upstream 1.5.5 or newer); empty: fetch Debian's 1.5.5 source package")

set(draco_uv_fetched_source_dir
    "${CMAKE_CURRENT_SOURCE_DIR}/third_party/debian-draco-1.5.5+dfsg-2")

function(draco_uv_fetch_debian_source out_dir)
  execute_process(
    COMMAND "${CMAKE_CURRENT_SOURCE_DIR}/scripts/fetch-draco-source.sh"
            "${draco_uv_fetched_source_dir}"
    RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR
      "Fetching Debian's Draco source failed (see above). Either fix apt or "
      "pass -DDRACO_SOURCE_DIR=<your Draco checkout>.")
  endif()
  set(${out_dir} "${draco_uv_fetched_source_dir}" PARENT_SCOPE)
endfunction()

function(draco_uv_patch_stamp source_dir patches out_stamp)
  set(stamp "source=${source_dir}")
  foreach(patch IN LISTS patches)
    file(SHA256 "${patch}" patch_hash)
    get_filename_component(patch_name "${patch}" NAME)
    string(APPEND stamp "\n${patch_name}=${patch_hash}")
  endforeach()
  set(${out_stamp} "${stamp}" PARENT_SCOPE)
endfunction()

function(draco_uv_copy_and_patch source_dir patched_dir patches)
  file(REMOVE_RECURSE "${patched_dir}")
  file(MAKE_DIRECTORY "${patched_dir}")
  file(GLOB top_level_entries LIST_DIRECTORIES true "${source_dir}/*")
  foreach(entry IN LISTS top_level_entries)
    get_filename_component(name "${entry}" NAME)
    if(NOT name STREQUAL ".git")
      file(COPY "${entry}" DESTINATION "${patched_dir}")
    endif()
  endforeach()
  # Our own repository so that git apply works relative to the copy even when
  # the build folder sits inside another work tree.
  execute_process(COMMAND git init -q "${patched_dir}" RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "git init failed in ${patched_dir}")
  endif()
  foreach(patch IN LISTS patches)
    execute_process(
      COMMAND git apply --whitespace=nowarn "${patch}"
      WORKING_DIRECTORY "${patched_dir}"
      RESULT_VARIABLE result
      ERROR_VARIABLE error)
    if(NOT result EQUAL 0)
      message(FATAL_ERROR
        "Patch ${patch} does not apply to ${source_dir}:\n${error}")
    endif()
    message(STATUS "draco-uv: applied ${patch}")
  endforeach()
endfunction()

# Sets DRACO_UV_PATCHED_SOURCE_DIR to a patched copy of the Draco source.
function(draco_uv_prepare_draco_source)
  set(source_dir "${DRACO_SOURCE_DIR}")
  if(source_dir STREQUAL "")
    draco_uv_fetch_debian_source(source_dir)
  endif()
  get_filename_component(source_dir "${source_dir}" ABSOLUTE)
  if(NOT EXISTS "${source_dir}/src/draco/core/draco_version.h")
    message(FATAL_ERROR "${source_dir} is not a Draco source tree.")
  endif()

  file(GLOB patches CONFIGURE_DEPENDS
       "${CMAKE_CURRENT_SOURCE_DIR}/patches/*.patch")
  list(SORT patches)
  draco_uv_patch_stamp("${source_dir}" "${patches}" stamp)
  set(patched_dir "${CMAKE_BINARY_DIR}/draco-patched")
  set(stamp_file "${patched_dir}/.draco-uv-patch-stamp")
  set(old_stamp "")
  if(EXISTS "${stamp_file}")
    file(READ "${stamp_file}" old_stamp)
  endif()
  if(NOT old_stamp STREQUAL stamp)
    draco_uv_copy_and_patch("${source_dir}" "${patched_dir}" "${patches}")
    file(WRITE "${stamp_file}" "${stamp}")
  endif()
  # Re-run configure when a patch changes.
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${patches})
  set(DRACO_UV_PATCHED_SOURCE_DIR "${patched_dir}" PARENT_SCOPE)
endfunction()
