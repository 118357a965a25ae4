# Embeds data files (IOR spectra, CIE tables, later shader templates) into the binary so
# that matc never looks for data next to itself at run time.
#
# matc_embed_files(<target> NAMESPACE <ns> BASE_DIR <dir> FILES <files...>)
# generates a source file defining `std::span<const matc::EmbeddedFile> <ns>::files()`
# with each file's path relative to BASE_DIR and its bytes.

set(_MATC_EMBED_SCRIPT "${CMAKE_CURRENT_LIST_DIR}/EmbedFilesScript.cmake")

function(matc_embed_files target)
  cmake_parse_arguments(ARG "" "NAMESPACE;BASE_DIR" "FILES" ${ARGN})
  string(REPLACE "::" "_" _stem "${ARG_NAMESPACE}")
  set(_out "${CMAKE_CURRENT_BINARY_DIR}/embedded_${_stem}.cpp")
  set(_abs_files "")
  foreach(_f IN LISTS ARG_FILES)
    get_filename_component(_abs "${_f}" ABSOLUTE BASE_DIR "${ARG_BASE_DIR}")
    list(APPEND _abs_files "${_abs}")
  endforeach()
  string(REPLACE ";" "|" _joined "${_abs_files}")
  add_custom_command(
    OUTPUT "${_out}"
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${_out} -DNAMESPACE=${ARG_NAMESPACE}
            -DBASE_DIR=${ARG_BASE_DIR} "-DFILES=${_joined}" -P "${_MATC_EMBED_SCRIPT}"
    DEPENDS ${_abs_files} "${_MATC_EMBED_SCRIPT}"
    COMMENT "Embedding ${ARG_NAMESPACE} data files"
    VERBATIM)
  target_sources(${target} PRIVATE "${_out}")
endfunction()
