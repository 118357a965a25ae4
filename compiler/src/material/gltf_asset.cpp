#include "gltf_asset.h"

#include <array>
#include <cstdint>
#include <filesystem>

#include <fmt/format.h>

#include "base/echoed_text.h"
#include "formats/glb_container.h"
#include "material/document_import.h"
#include "material/gltf_import.h"
#include "material/memory_files.h"

namespace matc {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kAllowedAsset = "a glTF 2.0 asset (docs/gltf.md)";

}  // namespace

std::string percent_decoded(std::string_view uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    const auto hex = [](char c) {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      if (c >= 'A' && c <= 'F') return c - 'A' + 10;
      return -1;
    };
    if (uri[i] == '%' && i + 2 < uri.size() && hex(uri[i + 1]) >= 0 && hex(uri[i + 2]) >= 0) {
      out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

namespace {

// Why a file URI (decoded) may not be read: absolute, with a scheme, or leaving the asset's
// folder. Empty when it may.
std::string uri_problem(const std::string& file) {
  return relative_file_problem(file, "URI", "the asset's folder");
}

// The file system tinygltf sees: only files inside the asset's folder, through matc's loader
// (size-limited). tinygltf joins each URI to the base folder we give it, kBase, and also tries
// "./"; every other path is refused.
constexpr std::string_view kBase = "matc-asset:";
struct AssetFiles {
  fs::path folder;
  const FileLoader* loader = nullptr;
  std::string refusal;  // the first refused URI and why
};

std::optional<std::string> uri_of(const std::string& path) {
  if (path.size() <= kBase.size() + 1 || path.compare(0, kBase.size(), kBase) != 0 ||
      path[kBase.size()] != '/')
    return std::nullopt;
  return path.substr(kBase.size() + 1);
}

bool file_exists(const std::string& path, void* user) {
  auto& files = *static_cast<AssetFiles*>(user);
  const std::optional<std::string> uri = uri_of(path);
  if (!uri) return false;  // tinygltf's fallback to the working directory
  if (const std::string problem = uri_problem(*uri); !problem.empty()) {
    if (files.refusal.empty())
      files.refusal = fmt::format("buffer URI '{}': {}", echoed(*uri, 128), problem);
    return false;
  }
  return true;
}

std::string expand_file_path(const std::string& path, void*) {
  return path;
}

bool read_whole_file(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                     void* user) {
  auto& files = *static_cast<AssetFiles*>(user);
  const std::optional<std::string> uri = uri_of(path);
  if (!uri || !uri_problem(*uri).empty()) return false;
  const LoadedFile loaded = (*files.loader)(files.folder / *uri, kMaxGltfFileBytes);
  if (!loaded.bytes) {
    if (files.refusal.empty())
      files.refusal = fmt::format("cannot read buffer '{}': {}", echoed(*uri, 128), loaded.error);
    if (error) *error = loaded.error;
    return false;
  }
  out->assign(loaded.bytes->begin(), loaded.bytes->end());
  return true;
}

bool write_whole_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

// Images are not decoded: matc reads materials.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
  return true;
}

// The first line of tinygltf's message.
std::string first_line(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? std::string("not a glTF 2.0 asset") : line;
}

class ModelChecks {
 public:
  ModelChecks(const tinygltf::Model& model, const std::string& path, Diagnostics& diagnostics)
      : model_(model), path_(path), diagnostics_(diagnostics) {}

  void run() {
    if (!sizes_bounded()) return;
    for (std::size_t i = 0; i < model_.bufferViews.size(); ++i)
      buffer_view(i);
    for (std::size_t i = 0; i < model_.accessors.size(); ++i)
      accessor(i);
    for (std::size_t i = 0; i < model_.images.size(); ++i)
      image(i);
    for (std::size_t i = 0; i < model_.textures.size(); ++i) {
      const int source = model_.textures[i].source;
      if (source < -1 || source >= static_cast<int>(model_.images.size()))
        error(fmt::format("textures[{}]", i), fmt::format("source {} is not an image", source),
              fmt::format("an index below {}", model_.images.size()));
    }
  }

 private:
  void error(const std::string& field, const std::string& message, const std::string& allowed) {
    diagnostics_.error({path_, 0, 0}, field, message, allowed);
  }

  bool sizes_bounded() {
    const std::array<std::pair<const char*, std::size_t>, 10> arrays{{
        {"materials", model_.materials.size()},
        {"accessors", model_.accessors.size()},
        {"bufferViews", model_.bufferViews.size()},
        {"buffers", model_.buffers.size()},
        {"images", model_.images.size()},
        {"textures", model_.textures.size()},
        {"meshes", model_.meshes.size()},
        {"nodes", model_.nodes.size()},
        {"samplers", model_.samplers.size()},
        {"animations", model_.animations.size()},
    }};
    bool bounded = true;
    for (const auto& [name, size] : arrays) {
      if (size > kMaxGltfArrayEntries) {
        error(name, fmt::format("{} entries", size),
              fmt::format("at most {} entries", kMaxGltfArrayEntries));
        bounded = false;
      }
    }
    return bounded;
  }

  void buffer_view(std::size_t i) {
    const tinygltf::BufferView& view = model_.bufferViews[i];
    const std::string field = fmt::format("bufferViews[{}]", i);
    if (view.buffer < 0 || view.buffer >= static_cast<int>(model_.buffers.size())) {
      error(field, fmt::format("buffer {} does not exist", view.buffer),
            fmt::format("an index below {}", model_.buffers.size()));
      return;
    }
    const std::size_t size = model_.buffers[static_cast<std::size_t>(view.buffer)].data.size();
    if (view.byteOffset > size || view.byteLength > size - view.byteOffset) {
      error(field,
            fmt::format("bytes {} to {} of buffer {}, which has {}", view.byteOffset,
                        static_cast<unsigned long long>(view.byteOffset) + view.byteLength,
                        view.buffer, size),
            "a range inside its buffer");
    }
  }

  // The bytes [offset, offset + length) must lie in bufferView `index`.
  bool in_view(const std::string& field, int index, std::uint64_t offset, std::uint64_t length) {
    if (index < 0 || index >= static_cast<int>(model_.bufferViews.size())) {
      error(field, fmt::format("bufferView {} does not exist", index),
            fmt::format("an index below {}", model_.bufferViews.size()));
      return false;
    }
    const std::uint64_t size = model_.bufferViews[static_cast<std::size_t>(index)].byteLength;
    if (offset > size || length > size - offset) {
      error(field,
            fmt::format("needs bytes {} to {} of bufferView {}, which has {}", offset,
                        offset + length, index, size),
            "a range inside its buffer view");
      return false;
    }
    return true;
  }

  void accessor(std::size_t i) {
    const tinygltf::Accessor& accessor = model_.accessors[i];
    const std::string field = fmt::format("accessors[{}]", i);
    const int component =
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(accessor.componentType));
    const int components =
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(accessor.type));
    if (component <= 0 || components <= 0) {
      error(field, "an unknown componentType or type", "the types glTF 2.0 defines");
      return;
    }
    const std::uint64_t element =
        static_cast<std::uint64_t>(component) * static_cast<std::uint64_t>(components);
    const std::uint64_t count = accessor.count;
    if (count > kMaxGltfFileBytes / element) {
      error(field, fmt::format("count {} of {}-byte elements", count, element),
            fmt::format("at most {} bytes of elements", kMaxGltfFileBytes));
      return;
    }
    if (accessor.bufferView >= 0 && count > 0) {
      const int view_index = accessor.bufferView;
      if (view_index >= static_cast<int>(model_.bufferViews.size())) {
        in_view(field, view_index, 0, 0);
        return;
      }
      const std::uint64_t declared_stride =
          model_.bufferViews[static_cast<std::size_t>(view_index)].byteStride;
      const std::uint64_t stride = declared_stride > 0 ? declared_stride : element;
      if (stride < element) {
        error(field, fmt::format("byteStride {} is less than its {}-byte element", stride, element),
              "a stride of at least the element's size");
        return;
      }
      in_view(field, view_index, accessor.byteOffset, stride * (count - 1) + element);
    }
    if (accessor.sparse.isSparse) {
      const auto sparse_count = static_cast<std::uint64_t>(std::max(accessor.sparse.count, 0));
      if (accessor.sparse.count < 1 || sparse_count > count) {
        error(field + ".sparse",
              fmt::format("count {} for an accessor of {}", accessor.sparse.count, count),
              "between 1 and the accessor's count");
        return;
      }
      const int index_size = tinygltf::GetComponentSizeInBytes(
          static_cast<std::uint32_t>(accessor.sparse.indices.componentType));
      if (index_size <= 0) {
        error(field + ".sparse.indices", "an unknown componentType", "UNSIGNED_BYTE, _SHORT, _INT");
        return;
      }
      in_view(field + ".sparse.indices", accessor.sparse.indices.bufferView,
              static_cast<std::uint64_t>(std::max(accessor.sparse.indices.byteOffset, 0)),
              sparse_count * static_cast<std::uint64_t>(index_size));
      in_view(field + ".sparse.values", accessor.sparse.values.bufferView,
              static_cast<std::uint64_t>(std::max(accessor.sparse.values.byteOffset, 0)),
              sparse_count * element);
    }
  }

  void image(std::size_t i) {
    const tinygltf::Image& image = model_.images[i];
    const std::string field = fmt::format("images[{}]", i);
    if (image.bufferView >= 0) {
      in_view(field, image.bufferView, 0, 0);
      return;
    }
    if (image.uri.empty() || image.uri.rfind("data:", 0) == 0) return;  // data URIs: decoded
    if (const std::string problem = uri_problem(percent_decoded(image.uri)); !problem.empty())
      error(field, fmt::format("uri '{}': {}", echoed(image.uri, 128), problem),
            "a relative path inside the asset's folder, or a data URI");
  }

  const tinygltf::Model& model_;
  const std::string& path_;
  Diagnostics& diagnostics_;
};

}  // namespace

std::optional<tinygltf::Model> read_gltf_asset(std::string_view bytes, const std::string& path,
                                               const FileLoader& loader, Diagnostics& diagnostics) {
  const bool binary = path_has_extension(path, ".glb");
  if (bytes.size() > kMaxGltfFileBytes) {
    diagnostics.error({path, 0, 0}, "", fmt::format("{} bytes", bytes.size()),
                      "a glTF asset of at most 256 MiB");
    return std::nullopt;
  }
  if (binary) {
    if (const std::string problem = glb_layout_problem(bytes); !problem.empty()) {
      diagnostics.error({path, 0, 0}, "", problem, "a GLB 2.0 container");
      return std::nullopt;
    }
  }
  AssetFiles files{fs::path(path).parent_path(), &loader, {}};
  tinygltf::TinyGLTF reader;
  reader.SetFsCallbacks(
      {&file_exists, &expand_file_path, &read_whole_file, &write_whole_file, &files});
  reader.SetImageLoader(&skip_image, nullptr);
  tinygltf::Model model;
  std::string error, warning;
  bool loaded = false;
  try {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    const auto size = static_cast<unsigned int>(bytes.size());
    const std::string base(kBase);
    loaded = binary ? reader.LoadBinaryFromMemory(&model, &error, &warning, data, size, base)
                    : reader.LoadASCIIFromString(&model, &error, &warning,
                                                 reinterpret_cast<const char*>(data), size, base);
  } catch (const std::exception& exception) {
    error = exception.what();
  }
  if (!loaded || !error.empty()) {
    // A refused or unreadable buffer is the reason; else tinygltf's first complaint.
    diagnostics.error({path, 0, 0}, "",
                      files.refusal.empty() ? echoed(first_line(error), 200) : files.refusal,
                      std::string(kAllowedAsset));
    return std::nullopt;
  }
  ModelChecks(model, path, diagnostics).run();
  if (diagnostics.has_errors()) return std::nullopt;
  return model;
}

}  // namespace matc
