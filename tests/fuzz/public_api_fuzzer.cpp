// libFuzzer target: the public API (matc/matc.h) as the WebAssembly and other faces call it, on
// any bytes. The first byte picks the options (the names the faces pass through, a wrong one
// among them), the document kind and whether files it names come from memory (InputFiles: the
// two halves of the rest as "a.csv" and "b.bin"); the rest is the document. What parses is
// compiled, its values read, its curves evaluated on cosines read from the input (NaN and values
// outside [0, 1] among them; Fbar and its reference on the same values as pairs, an output span of
// the wrong size once), its texts written, and matc eval's metal-rough mix evaluated there (the
// first value as the metalness). Allowed outcomes: MaterialError (an error, every line
// printable), std::invalid_argument for a bad option or cosine, std::logic_error for a bare metal's
// lobes; anything else (another exception, a crash, a sanitizer report) is a finding. The same
// bytes also go, before parsing, to the calls that take numbers or words rather than a document:
// Gulbrandsen's mapping both ways (std::invalid_argument allowed) and the SPIR-V calls (the bytes
// as a module, and as a GLSL shader; std::invalid_argument or std::runtime_error, every line
// printable).
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "matc/api/evaluation.h"
#include "matc/api/spirv.h"
#include "matc/api/tables.h"
#include "matc/matc.h"

namespace {

void require_printable(std::string_view text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F) __builtin_trap();
  }
}

void require_printable(const std::vector<matc::api::Diagnostic>& diagnostics) {
  for (const matc::api::Diagnostic& diagnostic : diagnostics) {
    for (const std::string* part : {&diagnostic.text, &diagnostic.path, &diagnostic.field,
                                    &diagnostic.message, &diagnostic.allowed})
      require_printable(*part);
  }
}

// Cosines from the input's bytes, 8 at a time as doubles (NaN, infinities and all), then a few
// in range.
std::vector<double> cosines_of(std::string_view text) {
  std::vector<double> mu = {0.0, 0.5, 1.0};
  for (std::size_t i = 0; i + 8 <= text.size() && mu.size() < 16; i += 8) {
    double value = 0.0;
    std::memcpy(&value, text.data() + i, sizeof value);
    mu.push_back(value);
  }
  return mu;
}

template <typename Call>
void allow_invalid_argument(const Call& call) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    require_printable(error.what());
  }
}

void require_printable_lines(std::string_view text) {
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if ((byte < 0x20 && c != '\n') || byte == 0x7F) __builtin_trap();
  }
}

void fuzz_numbers_and_words(std::string_view text) {
  const std::vector<double> values = cosines_of(text);  // at least 3, from the bytes after those
  const matc::api::Rgb first{values[values.size() - 3], values[values.size() - 2],
                             values[values.size() - 1]};
  const matc::api::Rgb second{values[0], values[1], values[2]};
  allow_invalid_argument([&] { (void)matc::api::ior_from_artistic({first, second}); });
  allow_invalid_argument([&] { (void)matc::api::artistic_from_ior({first, second}); });
  matc::api::SpirvWords words(text.size() / 4);
  if (!words.empty()) std::memcpy(words.data(), text.data(), words.size() * 4);
  const std::vector<std::string> names = {"main", std::string(text.substr(0, 8))};
  const std::vector<matc::api::SpirvWords> modules = {words, words};
  for (const auto& call :
       {std::function<void()>([&] { (void)matc::api::import_functions(words, names); }),
        std::function<void()>([&] { (void)matc::api::link_spirv(modules, text.substr(0, 8)); }),
        std::function<void()>(
            [&] { (void)matc::api::compile_shader("glsl", text, "fuzz.comp"); })}) {
    try {
      call();
    } catch (const std::invalid_argument& error) {
      require_printable_lines(error.what());
    } catch (const std::runtime_error& error) {
      require_printable_lines(error.what());
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  // "auto": each material its own basis (f82 for the F82-tint ones, powers for the rest).
  constexpr std::array<const char*, 4> kBases = {"", "paper", "auto", "no\x1b[31mbasis"};
  constexpr std::array<const char*, 4> kSpaces = {"", "acescg", "lin_displayp3", "\xff"};
  constexpr std::array<const char*, 2> kMappings = {"", "desaturate"};
  const unsigned pick = data[0];
  const matc::api::CompileOptions options{kBases[pick & 3], kSpaces[(pick >> 2) & 3],
                                          kMappings[(pick >> 4) & 1]};
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  if ((pick & 0x80) != 0) fuzz_numbers_and_words(text);
  const char* path = (pick & 0x20) != 0 ? "fuzz.mtlx" : "fuzz.json";
  std::vector<matc::api::Material> materials;
  const matc::api::InputFiles files{{"a.csv", std::string(text.substr(text.size() / 2))},
                                    {"b.bin", std::string(text.substr(0, text.size() / 2))}};
  try {
    materials = (pick & 0x40) != 0 ? matc::api::parse_materials(text, path, files)
                                   : matc::api::parse_materials(text, path);
  } catch (const matc::api::MaterialError& error) {
    if (error.diagnostics().empty()) __builtin_trap();
    require_printable(error.diagnostics());
    return 0;
  }
  if (text.find('\0') != std::string_view::npos) __builtin_trap();  // a NUL is never accepted
  const std::vector<double> mu = cosines_of(text);
  for (const matc::api::Material& material : materials) {
    require_printable(material.diagnostics());
    (void)material.inputs();
    (void)material.roughness();
    (void)material.color_space();
    allow_invalid_argument([&] {
      const matc::api::CompiledMaterial compiled = matc::api::compile(material, options);
      require_printable(compiled.diagnostics());
      allow_invalid_argument([&] { (void)compiled.fresnel(mu); });
      allow_invalid_argument([&] { (void)compiled.exact(mu); });
      allow_invalid_argument([&] { (void)compiled.schlick(mu); });
      allow_invalid_argument([&] { (void)compiled.f82_tint(mu); });
      if (compiled.coat()) allow_invalid_argument([&] { (void)compiled.coated_fresnel(mu); });
      std::vector<double> rgb(3 * mu.size() - 1);
      allow_invalid_argument([&] { compiled.fresnel(mu, rgb); });
      const std::span<const double> ndotv(mu.data(), mu.size() / 2);
      const std::span<const double> roughness(mu.data() + mu.size() / 2, mu.size() / 2);
      // A small table of its basis: the default one takes seconds to bake under the sanitizers.
      const matc::api::PreintegratedTable table =
          matc::api::preintegrated_table({compiled.basis(), 8, 16, "f32"});
      allow_invalid_argument([&] { (void)compiled.fbar(ndotv, roughness, table); });
      allow_invalid_argument([&] { (void)compiled.fbar_reference(ndotv, roughness, 16); });
      (void)compiled.ior();
      (void)compiled.artistic();
      if (compiled.json().empty()) __builtin_trap();
      const matc::api::TextOutputs texts(options);
      for (const char* language : {"glsl", "hlsl", "wgsl"})
        if (texts.material_source(language, compiled).empty()) __builtin_trap();
      if (texts.material_json(compiled).empty()) __builtin_trap();
    });
    // matc eval's metal-rough mix (--metalness) at the input's cosines, the first of them as the
    // metalness (NaN and values outside [0, 1] among them); F only (Fbar bakes a full table).
    if (!mu.empty()) {
      matc::api::EvaluationOptions evaluation;
      evaluation.mu.assign(mu.begin() + 1, mu.end());
      evaluation.metalness = mu.front();
      evaluation.compile = options;
      allow_invalid_argument([&] {
        if (matc::api::evaluate(material, evaluation).empty()) __builtin_trap();
      });
    }
  }
  return 0;
}
