# libmatc's sources in two lists: MATC_CORE_SOURCES, the compile path every build of the library
# has (reading, fitting, compiling, evaluating, the texts; nothing outside the C++ library and
# header-only dependencies; MaterialX read by rapidxml), and MATC_NATIVE_SOURCES, the rest
# (glslang, SPIRV-Tools, OpenEXR, pugixml, threads, files). The native library takes both (and
# reads MaterialX with pugixml); the WebAssembly one (js/) the first. Paths are relative to
# compiler/.
set(MATC_CORE_SOURCES
  src/spirv/shader_language.cpp
  src/base/diagnostics.cpp
  src/base/echoed_text.cpp
  src/base/utf8.cpp
  src/base/csv_table.cpp
  src/base/number_text.cpp
  src/base/embedded_file.cpp
  src/base/content_hash.cpp
  src/optics/coat.cpp
  src/optics/color_space.cpp
  src/optics/fresnel.cpp
  src/optics/gamut.cpp
  src/optics/gulbrandsen.cpp
  src/optics/reflectance_curve.cpp
  src/optics/spectrum.cpp
  src/optics/spectral.cpp
  src/optics/thin_film.cpp
  src/optics/presets.cpp
  src/fit/minimax.cpp
  src/fit/coefficients.cpp
  src/fit/nonnegative_curve.cpp
  src/fit/accuracy.cpp
  src/material/located_json.cpp
  src/material/located_json_reader.cpp
  src/material/load_file.cpp
  src/material/memory_files.cpp
  src/material/material.cpp
  src/material/basis_pin.cpp
  src/material/materialx_file.cpp
  src/material/materialx_import.cpp
  src/material/materialx_document.cpp
  src/material/materialx_models.cpp
  src/material/xml_well_formed.cpp
  src/material/xml_tree.cpp
  src/material/xml_tree_rapidxml.cpp
  src/material/document_import.cpp
  src/material/gltf_asset.cpp
  src/material/gltf_import.cpp
  src/material/tinygltf_implementation.cpp
  src/material/parse.cpp
  src/material/suggestion.cpp
  src/material/material_input.cpp
  src/base/json_format.cpp
  src/lut/microfacet_samples.cpp
  src/lut/preintegrate.cpp
  src/lut/lut_atlas.cpp
  src/lut/energy.cpp
  src/formats/table_format.cpp
  src/formats/glb_container.cpp
  src/compile/compile.cpp
  src/compile/basis_choice.cpp
  src/compile/f0_table.cpp
  src/compile/film_tables.cpp
  src/lut/split_sum_reference.cpp
  src/emit/template.cpp
  src/emit/shader_literals.cpp
  src/emit/material_json.cpp
  src/emit/gltf_fresnel_extension.cpp
  src/emit/shader_library.cpp
  src/emit/material_snippet.cpp
  src/emit/text_outputs.cpp
  src/emit/output_layout.cpp
  src/options/option_names.cpp
  src/api/diagnostics.cpp
  src/api/checked_values.cpp
  src/api/options.cpp
  src/api/layout.cpp
  src/api/material.cpp
  src/api/compiled_material.cpp
  src/api/gulbrandsen.cpp
  src/api/text_outputs.cpp
  src/api/gltf.cpp
)
set(MATC_NATIVE_SOURCES
  src/material/xml_tree_pugixml.cpp
  src/api/batch.cpp
  src/api/batch_events.cpp
  src/api/build.cpp
  src/api/tables.cpp
  src/api/fbar_reference.cpp
  src/api/files.cpp
  src/api/gltf_files.cpp
  src/api/report.cpp
  src/api/basis.cpp
  src/api/regeneration.cpp
  src/api/spirv.cpp
  src/api/bake.cpp
  src/api/evaluation.cpp
  src/api/coated_evaluation.cpp
  src/api/metal_rough_evaluation.cpp
  src/basis/training_set.cpp
  src/basis/basis_polynomial_fit.cpp
  src/basis/basis_fit.cpp
  src/fit/coefficient_table.cpp
  src/fit/conductor_solver.cpp
  src/base/exclusive_file.cpp
  src/base/pending_file.cpp
  src/lut/analytic_lut_fit.cpp
  src/lut/comparison_lobes.cpp
  src/formats/texel_bytes.cpp
  src/formats/ktx2_writer.cpp
  src/formats/dds_writer.cpp
  src/formats/texture_file.cpp
  src/lut/header_writer.cpp
  src/lut/layered_reference.cpp
  src/lut/lut_files.cpp
  src/lut/coefficient_table_files.cpp
  src/lut/film_table_files.cpp
  src/lut/default_lut_hash_lookup.cpp
  src/generated/default_lut_hashes.cpp
  src/ltc/ggx_lobe.cpp
  src/ltc/ltc_fit.cpp
  src/ltc/lobe_polygons.cpp
  src/ltc/polygon_light.cpp
  src/ltc/area_light_reference.cpp
  src/ltc/ltc_table_files.cpp
  src/bake/bake_asset.cpp
  src/bake/bake_inputs.cpp
  src/bake/baked_texture_files.cpp
  src/bake/coefficient_textures.cpp
  src/bake/image_map.cpp
  src/bake/openexr_decode.cpp
  src/emit/material_module_template.cpp
  src/emit/word_array_source.cpp
  src/generated/material_module_templates.cpp
  src/generated/library_module_cache.cpp
  src/emit/c_header.cpp
  src/emit/validation_kernel.cpp
  src/emit/fullscreen_shaders.cpp
  src/emit/build.cpp
  src/emit/shared_tables.cpp
  src/emit/library_module.cpp
  src/emit/library_module_cache.cpp
  src/emit/manifest_writer.cpp
  src/report/material_curves.cpp
  src/report/fresnel_plot.cpp
  src/report/report_page.cpp
  src/spirv/spirv_instructions.cpp
  src/spirv/shader_compiler.cpp
  src/spirv/spirv_tools.cpp
  src/spirv/linkage.cpp
  src/spirv/module_patch.cpp
  src/pipeline/atomic_file.cpp
  src/pipeline/output_sink.cpp
  src/pipeline/depfile.cpp
  src/pipeline/in_order.cpp
  src/pipeline/unique_names.cpp
  src/pipeline/inputs_in_output_directory.cpp
  src/pipeline/worker_count.cpp
  src/pipeline/batch_reporter.cpp
  src/pipeline/compile_batch.cpp
  src/pipeline/bake_batch.cpp
  src/pipeline/import_batch.cpp
)

set(_MATC_SOURCE_ROOT ${CMAKE_CURRENT_LIST_DIR}/..)

# matc_embed_core_files(<target>): the measured spectra (compiler/data) and the shader templates
# (templates/), embedded in the library (cmake/EmbedFiles.cmake).
function(matc_embed_core_files target)
  file(GLOB_RECURSE _data_files CONFIGURE_DEPENDS RELATIVE ${_MATC_SOURCE_ROOT}/compiler/data
       ${_MATC_SOURCE_ROOT}/compiler/data/*.csv)
  list(SORT _data_files)
  matc_embed_files(${target} NAMESPACE matc::embedded_data
    BASE_DIR ${_MATC_SOURCE_ROOT}/compiler/data FILES ${_data_files})
  file(GLOB_RECURSE _template_files CONFIGURE_DEPENDS RELATIVE ${_MATC_SOURCE_ROOT}/templates
       ${_MATC_SOURCE_ROOT}/templates/glsl/* ${_MATC_SOURCE_ROOT}/templates/hlsl/*
       ${_MATC_SOURCE_ROOT}/templates/wgsl/* ${_MATC_SOURCE_ROOT}/templates/c/*)
  list(SORT _template_files)
  matc_embed_files(${target} NAMESPACE matc::embedded_templates
    BASE_DIR ${_MATC_SOURCE_ROOT}/templates FILES ${_template_files})
endfunction()
