# matc_add_materials(TARGET <target> OUTPUT_DIR <dir> MATERIALS <files...>
#                    [EMIT <kinds...>] [LUT_FORMAT ktx2|dds|raw|header] [OPTIONS <matc args...>]
#                    [PER_MATERIAL])
#
# Adds one build step that runs `matc` over MATERIALS into OUTPUT_DIR (in parallel inside matc),
# with a depfile so that editing a material, a spectral file it names, or updating matc reruns it,
# and nothing else does. With PER_MATERIAL, one step per material (`matc --no-shared`, its own
# depfile) plus one for the shared files (`matc --shared-only`) instead: editing one material
# reruns one small step, which suits very large material sets and distributed builds; the files
# are the same bytes, less matc_manifest.json, which only a batch writes (docs/scaling.md). The generated per-material headers become sources of TARGET and
# OUTPUT_DIR one of its include directories, so `#include "<name>.h"` works and the target is built
# after its materials. EMIT selects outputs (glsl hlsl wgsl spirv header json lut
# coefficient-table ltc; default all). Use one OUTPUT_DIR per call (a second call with the same one is an error):
# every call writes the shared files matc_fresnel.*, matc_lut.*, matc_coefficient_table.* and
# matc_ltc.*.
# Material names are read from the files at configure time (changing one reconfigures), and so
# are their film blocks: a filmed metal's own table (<name>.film.<ext>, with lut among EMIT) is one
# of its outputs (docs/thin-film.md).
include("${CMAKE_CURRENT_LIST_DIR}/MatcOutputLayout.cmake")

# _matc_json_name(<path> <caller> <kind> <out_var>): the "name" field of a JSON file (material or
# bake asset), read at configure time; a file without one stops CMake with a pointer to matc.
function(_matc_json_name path caller kind out_var)
  if(path MATCHES "\\.[mM][tT][lL][xX]$")
    message(FATAL_ERROR "${caller}: ${path} is a MaterialX document, whose outputs are named after "
            "the materials inside it: write its material files with `matc import` and list those "
            "(docs/interchange.md)")
  endif()
  if(path MATCHES "\\.([gG][lL][tT][fF]|[gG][lL][bB])$")
    message(FATAL_ERROR "${caller}: ${path} is a glTF asset, whose outputs are named after the "
            "metals inside it: write their material files with `matc import` and list those "
            "(docs/gltf.md)")
  endif()
  file(READ "${path}" _json)
  string(JSON _name ERROR_VARIABLE _error GET "${_json}" name)
  if(_error)
    message(FATAL_ERROR "${caller}: ${path}: no ${kind} name (${_error}); run matc on it for details")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${path}")
  set(${out_var} "${_name}" PARENT_SCOPE)
endfunction()

# _matc_json_has_film(<path> <out_var>): whether a material file gives its metal a film that shows
# (docs/thin-film.md: a thickness and a coverage above 0, an index other than that of the medium
# it lies in, air or a coat, "Under a coat"; matc's has_visible_film), which compiles
# to its own table, <name>.film.<ext>. A malformed film block is matc's to refuse: it is not one.
function(_matc_json_has_film path out_var)
  file(READ "${path}" _json)
  set(_film FALSE)
  string(JSON _thickness ERROR_VARIABLE _error GET "${_json}" film thickness)
  if(NOT _error AND _thickness MATCHES "^[0-9.eE+-]+$" AND _thickness GREATER 0)
    string(JSON _weight ERROR_VARIABLE _weight_error GET "${_json}" film weight)
    if(_weight_error)
      set(_weight 1)  # a film block that names no coverage covers the metal
    endif()
    string(JSON _ior ERROR_VARIABLE _ior_error GET "${_json}" film ior)
    if(_ior_error)
      set(_ior 1.4)  # OpenPBR's default film index
    endif()
    # A film of the index of the medium it lies in is that medium: the bare metal, no table. Under a
    # partial coat the uncoated part sees it in air.
    string(JSON _coat ERROR_VARIABLE _coat_error GET "${_json}" coat)
    set(_seen_in_air TRUE)
    set(_seen_in_coat FALSE)
    if(NOT _coat_error)
      string(JSON _coat_weight ERROR_VARIABLE _coat_weight_error GET "${_json}" coat weight)
      if(NOT _coat_weight_error AND _coat_weight MATCHES "^[0-9.eE+-]+$" AND _coat_weight GREATER_EQUAL 1)
        set(_seen_in_air FALSE)
      elseif(_coat_weight_error)
        set(_seen_in_air FALSE)  # a coat block that names no weight covers the metal
      endif()
      string(JSON _coat_ior ERROR_VARIABLE _coat_ior_error GET "${_json}" coat ior)
      if(_coat_ior_error)
        set(_coat_ior 1.6)  # the coat's default index
      endif()
      if(NOT _ior EQUAL _coat_ior)
        set(_seen_in_coat TRUE)
      endif()
    endif()
    if(_seen_in_air AND NOT _ior EQUAL 1)
      set(_shows TRUE)
    else()
      set(_shows ${_seen_in_coat})
    endif()
    if(_weight MATCHES "^[0-9.eE+-]+$" AND _weight GREATER 0 AND _shows)
      set(_film TRUE)
    endif()
  endif()
  set(${out_var} ${_film} PARENT_SCOPE)
endfunction()

function(matc_add_materials)
  cmake_parse_arguments(ARG "PER_MATERIAL" "TARGET;OUTPUT_DIR;LUT_FORMAT" "MATERIALS;EMIT;OPTIONS"
                        ${ARGN})
  if(NOT ARG_TARGET OR NOT TARGET "${ARG_TARGET}")
    message(FATAL_ERROR "matc_add_materials: TARGET must name an existing target")
  endif()
  if(NOT ARG_OUTPUT_DIR OR NOT ARG_MATERIALS)
    message(FATAL_ERROR "matc_add_materials: OUTPUT_DIR and MATERIALS are required")
  endif()
  if(NOT ARG_EMIT)
    set(ARG_EMIT ${_matc_output_kinds})
  endif()
  if(NOT ARG_LUT_FORMAT)
    set(ARG_LUT_FORMAT ktx2)
  endif()
  if(NOT DEFINED _matc_table_extension_${ARG_LUT_FORMAT})
    message(FATAL_ERROR "matc_add_materials: LUT_FORMAT '${ARG_LUT_FORMAT}' is not one of ktx2, dds, raw, header")
  endif()
  get_filename_component(_dir "${ARG_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  get_property(_used GLOBAL PROPERTY MATC_ADD_MATERIALS_OUTPUT_DIRS)
  if("${_dir}" IN_LIST _used)
    message(FATAL_ERROR "matc_add_materials: OUTPUT_DIR ${_dir} is already used by another call; "
                        "every call writes matc_fresnel.*, matc_lut.*, matc_coefficient_table.* and matc_ltc.*, so give each its own")
  endif()
  set_property(GLOBAL APPEND PROPERTY MATC_ADD_MATERIALS_OUTPUT_DIRS "${_dir}")

  foreach(_kind IN LISTS ARG_EMIT)
    if(NOT _kind IN_LIST _matc_output_kinds)
      list(JOIN _matc_output_kinds ", " _kinds)
      message(FATAL_ERROR "matc_add_materials: EMIT '${_kind}' is not one of ${_kinds}")
    endif()
  endforeach()

  # Outputs in the order matc's depfile names them (Ninja checks the first): the shared files,
  # then each material's in input order. The names come from cmake/MatcOutputLayout.cmake.
  set(_outputs "")
  foreach(_kind IN LISTS _matc_output_kinds)
    if(NOT _kind IN_LIST ARG_EMIT)
      continue()
    endif()
    if(DEFINED _matc_shared_file_${_kind})
      list(APPEND _outputs "${_dir}/${_matc_shared_file_${_kind}}")
    elseif(DEFINED _matc_table_stem_${_kind})
      set(_table "${_dir}/${_matc_table_stem_${_kind}}${_matc_table_extension_${ARG_LUT_FORMAT}}")
      list(APPEND _outputs "${_table}" "${_table}.json")
    endif()
  endforeach()
  if("json" IN_LIST ARG_EMIT AND NOT ARG_PER_MATERIAL)
    list(APPEND _outputs "${_dir}/${_matc_manifest_file}")
  endif()
  list(JOIN ARG_EMIT "," _emit)
  if(ARG_PER_MATERIAL)
    add_custom_command(
      OUTPUT ${_outputs}
      COMMAND matc::cli -q --shared-only --emit ${_emit} --lut ${ARG_LUT_FORMAT} ${ARG_OPTIONS}
              -o "${_dir}"
      DEPENDS matc::cli
      COMMENT "matc: shared files into ${_dir}"
      VERBATIM)
  endif()
  set(_materials "")
  foreach(_material IN LISTS ARG_MATERIALS)
    get_filename_component(_path "${_material}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    _matc_json_name("${_path}" matc_add_materials material _name)
    string(TOLOWER "${_name}" _lower_name)
    if(_lower_name IN_LIST _matc_shared_stems)
      list(JOIN _matc_shared_stems ", " _stems)
      message(FATAL_ERROR "matc_add_materials: ${_path}: the material name '${_name}' names a file every build writes; give a name other than ${_stems} (ignoring case)")
    endif()
    list(APPEND _materials "${_path}")
    set(_material_outputs "")
    foreach(_kind IN LISTS _matc_output_kinds)
      if(_kind IN_LIST ARG_EMIT AND DEFINED _matc_material_extension_${_kind})
        list(APPEND _material_outputs "${_dir}/${_name}${_matc_material_extension_${_kind}}")
      endif()
    endforeach()
    # A filmed metal's own table, written with the tables.
    _matc_json_has_film("${_path}" _film)
    if(_film AND "lut" IN_LIST ARG_EMIT)
      list(APPEND _material_outputs
           "${_dir}/${_name}${_matc_film_table_infix}${_matc_table_extension_${ARG_LUT_FORMAT}}")
    endif()
    list(APPEND _outputs ${_material_outputs})
    if(ARG_PER_MATERIAL AND _material_outputs)
      add_custom_command(
        OUTPUT ${_material_outputs}
        COMMAND matc::cli -q --no-shared --emit ${_emit} --lut ${ARG_LUT_FORMAT} ${ARG_OPTIONS}
                --depfile "${_dir}/${_name}.d" -o "${_dir}" "${_path}"
        DEPENDS "${_path}" matc::cli
        DEPFILE "${_dir}/${_name}.d"
        COMMENT "matc: ${_name}"
        VERBATIM)
    endif()
  endforeach()
  if(ARG_PER_MATERIAL)
    target_sources(${ARG_TARGET} PRIVATE ${_outputs})
    target_include_directories(${ARG_TARGET} PRIVATE "${_dir}")
    return()
  endif()

  list(LENGTH _materials _count)
  add_custom_command(
    OUTPUT ${_outputs}
    COMMAND matc::cli -q --emit ${_emit} --lut ${ARG_LUT_FORMAT} ${ARG_OPTIONS}
            --depfile "${_dir}/matc.d" -o "${_dir}" ${_materials}
    DEPENDS ${_materials} matc::cli
    DEPFILE "${_dir}/matc.d"
    COMMENT "matc: compiling ${_count} material(s) into ${_dir}"
    VERBATIM)
  target_sources(${ARG_TARGET} PRIVATE ${_outputs})
  target_include_directories(${ARG_TARGET} PRIVATE "${_dir}")
endfunction()
