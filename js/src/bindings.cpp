// The WebAssembly face: embind over the public API (matc/matc.h) only. No C++ exception leaves a
// call: each is caught here and handed to JavaScript as an {error} value, which the ES module
// (js/package/index.mjs) throws as a MatcError, so a bad input leaves the instance usable.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <exception>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "matc/matc.h"

namespace {

using emscripten::val;

val array_of(std::span<const double> values) {
  return val::global("Float64Array")
      .new_(emscripten::typed_memory_view(values.size(), values.data()));
}

val rgb_of(const matc::api::Rgb& rgb) {
  return array_of(rgb);
}

val rows_of(const matc::api::CoefficientRows& rows) {
  val out = val::array();
  for (const auto& row : rows)
    out.call<void>("push", array_of(row));
  return out;
}

val diagnostic_of(const matc::api::Diagnostic& diagnostic) {
  val out = val::object();
  out.set("severity", diagnostic.severity);
  out.set("path", diagnostic.path);
  out.set("line", static_cast<double>(diagnostic.line));
  out.set("column", static_cast<double>(diagnostic.column));
  out.set("field", diagnostic.field);
  out.set("message", diagnostic.message);
  out.set("allowed", diagnostic.allowed);
  out.set("text", diagnostic.text);
  return out;
}

val diagnostics_of(const std::vector<matc::api::Diagnostic>& diagnostics) {
  val out = val::array();
  for (const matc::api::Diagnostic& diagnostic : diagnostics)
    out.call<void>("push", diagnostic_of(diagnostic));
  return out;
}

val failure(std::string kind, std::string message,
            const std::vector<matc::api::Diagnostic>& diagnostics = {}) {
  val error = val::object();
  error.set("kind", std::move(kind));
  error.set("message", std::move(message));
  error.set("diagnostics", diagnostics_of(diagnostics));
  val out = val::object();
  out.set("error", error);
  return out;
}

// Runs `call`, whose result becomes {value}; any exception becomes {error: {kind, message}}.
template <typename Call>
val guarded(const Call& call) {
  try {
    val out = val::object();
    out.set("value", call());
    return out;
  } catch (const matc::api::MaterialError& error) {
    return failure("material", error.what(), error.diagnostics());
  } catch (const std::invalid_argument& error) {
    return failure("argument", error.what());
  } catch (const std::bad_alloc&) {
    return failure("memory", "out of memory");
  } catch (const std::exception& error) {
    return failure("internal", error.what());
  }
}

std::vector<double> doubles_of(const val& array) {
  return emscripten::convertJSArrayToNumberVector<double>(array);
}

class JsMaterial {
 public:
  explicit JsMaterial(matc::api::Material material) : material_(std::move(material)) {}
  const matc::api::Material& material() const { return material_; }
  val describe() const {
    val out = val::object();
    out.set("name", material_.name());
    out.set("model", material_.model());
    out.set("path", material_.path());
    out.set("json", material_.json());
    out.set("coated", material_.coated());
    out.set("diagnostics", diagnostics_of(material_.diagnostics()));
    return out;
  }

 private:
  matc::api::Material material_;
};

class JsCompiled {
 public:
  explicit JsCompiled(matc::api::CompiledMaterial compiled) : compiled_(std::move(compiled)) {}
  const matc::api::CompiledMaterial& compiled() const { return compiled_; }

  val describe() const {
    val out = val::object();
    out.set("name", compiled_.name());
    out.set("basis", compiled_.basis());
    out.set("coefficients", rows_of(compiled_.coefficients()));
    out.set("f0", rgb_of(compiled_.f0()));
    out.set("f82", rgb_of(compiled_.f82()));
    const matc::api::Accuracy accuracy = compiled_.accuracy();
    val fit = val::object();
    fit.set("samples", static_cast<double>(accuracy.samples));
    fit.set("maxError", rgb_of(accuracy.max_error));
    fit.set("rmsError", rgb_of(accuracy.rms_error));
    fit.set("schlickMaxError", rgb_of(accuracy.schlick_max_error));
    fit.set("schlickRmsError", rgb_of(accuracy.schlick_rms_error));
    fit.set("f82TintMaxError", rgb_of(accuracy.f82_tint_max_error));
    fit.set("f82TintRmsError", rgb_of(accuracy.f82_tint_rms_error));
    out.set("accuracy", fit);
    if (const std::optional<matc::api::Coat> coat = compiled_.coat()) {
      val c = val::object();
      c.set("weight", coat->weight);
      c.set("ior", coat->ior);
      c.set("roughness", coat->roughness);
      c.set("color", rgb_of(coat->color));
      c.set("underCoatCoefficients", rows_of(coat->under_coat_coefficients));
      c.set("coatCoefficients", array_of(coat->coat_coefficients));
      c.set("layeredMaxError", rgb_of(coat->layered_max_error));
      out.set("coat", c);
    } else {
      out.set("coat", val::null());
    }
    // A filmed metal's own table (docs/thin-film.md), RGBA texels to upload as a texture.
    if (const std::optional<matc::api::FilmTable> film = compiled_.film_table()) {
      val table = val::object();
      table.set("width", static_cast<double>(film->width));
      table.set("height", static_cast<double>(film->height));
      table.set("texels",
                val::global("Float32Array")
                    .new_(emscripten::typed_memory_view(film->texels.size(), film->texels.data())));
      out.set("filmTable", table);
    } else {
      out.set("filmTable", val::null());
    }
    out.set("diagnostics", diagnostics_of(compiled_.diagnostics()));
    return out;
  }

  val fresnel(const val& mu) const {
    return guarded([&] { return array_of(compiled_.fresnel(doubles_of(mu))); });
  }
  val exact(const val& mu) const {
    return guarded([&] { return array_of(compiled_.exact(doubles_of(mu))); });
  }
  val schlick(const val& mu) const {
    return guarded([&] { return array_of(compiled_.schlick(doubles_of(mu))); });
  }
  val f82_tint(const val& mu) const {
    return guarded([&] { return array_of(compiled_.f82_tint(doubles_of(mu))); });
  }
  val coated_fresnel(const val& mu) const {
    return guarded([&] {
      const matc::api::CompiledMaterial::Lobes lobes = compiled_.coated_fresnel(doubles_of(mu));
      val out = val::object();
      out.set("base", array_of(lobes.base));
      out.set("coat", array_of(lobes.coat));
      return out;
    });
  }
  val fbar(const val& ndotv, const val& roughness) const {
    return guarded(
        [&] { return array_of(compiled_.fbar(doubles_of(ndotv), doubles_of(roughness))); });
  }

 private:
  matc::api::CompiledMaterial compiled_;
};

class JsTextOutputs {
 public:
  explicit JsTextOutputs(matc::api::TextOutputs texts) : texts_(std::move(texts)) {}
  val library_source(const std::string& language) const {
    return guarded([&] { return val(texts_.library_source(language)); });
  }
  val material_source(const std::string& language, const JsCompiled& compiled) const {
    return guarded([&] { return val(texts_.material_source(language, compiled.compiled())); });
  }
  val material_json(const JsCompiled& compiled) const {
    return guarded([&] { return val(texts_.material_json(compiled.compiled())); });
  }
  std::string basis() const { return texts_.basis(); }

 private:
  matc::api::TextOutputs texts_;
};

matc::api::CompileOptions options_of(const std::string& basis, const std::string& color_space,
                                     const std::string& gamut_mapping) {
  return {basis, color_space, gamut_mapping};
}

// The files an input names, given as a JS object of name -> text or bytes (index.mjs checks
// the values' types); undefined or null: none given, the input reads no file.
std::optional<matc::api::InputFiles> files_of(const val& files) {
  if (files.isUndefined() || files.isNull()) return std::nullopt;
  matc::api::InputFiles out;
  const val names = val::global("Object").call<val>("keys", files);
  const auto count = names["length"].as<unsigned>();
  for (unsigned i = 0; i < count; ++i) {
    const std::string name = names[i].as<std::string>();
    out.emplace(name, files[name].as<std::string>());
  }
  return out;
}

val parse_materials(const std::string& text, const std::string& path, const val& files) {
  return guarded([&] {
    val out = val::array();
    const std::optional<matc::api::InputFiles> given = files_of(files);
    for (matc::api::Material& material : given ? matc::api::parse_materials(text, path, *given)
                                               : matc::api::parse_materials(text, path))
      out.call<void>("push", val(JsMaterial(std::move(material))));
    return out;
  });
}

val compile(const JsMaterial& material, const std::string& basis, const std::string& color_space,
            const std::string& gamut_mapping) {
  return guarded([&] {
    return val(JsCompiled(
        matc::api::compile(material.material(), options_of(basis, color_space, gamut_mapping))));
  });
}

val text_outputs(const std::string& basis, const std::string& color_space,
                 const std::string& gamut_mapping) {
  return guarded([&] {
    return val(
        JsTextOutputs(matc::api::TextOutputs(options_of(basis, color_space, gamut_mapping))));
  });
}

// {bytes: Uint8Array, materials: [{material, compiled}]}: the asset written back
// with each metal's MATC_materials_fresnel (matc/api/gltf.h).
val compile_gltf(const std::string& bytes, const std::string& path, const std::string& basis,
                 const std::string& color_space, const std::string& gamut_mapping,
                 const val& files) {
  return guarded([&] {
    const matc::api::CompileOptions options = options_of(basis, color_space, gamut_mapping);
    const std::optional<matc::api::InputFiles> given = files_of(files);
    matc::api::GltfAsset asset = given ? matc::api::compile_gltf(bytes, path, options, *given)
                                       : matc::api::compile_gltf(bytes, path, options);
    val out = val::object();
    out.set("bytes", val::global("Uint8Array")
                         .new_(emscripten::typed_memory_view(
                             asset.bytes.size(),
                             reinterpret_cast<const unsigned char*>(asset.bytes.data()))));
    val materials = val::array();
    for (matc::api::CompiledMaterial& compiled : asset.materials) {
      val entry = val::object();
      entry.set("material", val(JsMaterial(compiled.material())));
      entry.set("compiled", val(JsCompiled(std::move(compiled))));
      materials.call<void>("push", entry);
    }
    out.set("materials", materials);
    return out;
  });
}

val spectral_presets() {
  val out = val::array();
  for (const std::string& name : matc::api::spectral_presets())
    out.call<void>("push", name);
  return out;
}

}  // namespace

EMSCRIPTEN_BINDINGS(matc) {
  emscripten::class_<JsMaterial>("Material").function("describe", &JsMaterial::describe);
  emscripten::class_<JsCompiled>("CompiledMaterial")
      .function("describe", &JsCompiled::describe)
      .function("fresnel", &JsCompiled::fresnel)
      .function("exact", &JsCompiled::exact)
      .function("schlick", &JsCompiled::schlick)
      .function("f82Tint", &JsCompiled::f82_tint)
      .function("coatedFresnel", &JsCompiled::coated_fresnel)
      .function("fbar", &JsCompiled::fbar);
  emscripten::class_<JsTextOutputs>("TextOutputs")
      .function("librarySource", &JsTextOutputs::library_source)
      .function("materialSource", &JsTextOutputs::material_source)
      .function("materialJson", &JsTextOutputs::material_json)
      .function("basis", &JsTextOutputs::basis);
  emscripten::function("parseMaterials", &parse_materials);
  emscripten::function("compile", &compile);
  emscripten::function("textOutputs", &text_outputs);
  emscripten::function("compileGltf", &compile_gltf);
  emscripten::function("spectralPresets", &spectral_presets);
  emscripten::function("readsMaterialX", &matc::api::reads_materialx);
}
