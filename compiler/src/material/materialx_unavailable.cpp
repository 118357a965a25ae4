// MaterialX import for a build without an XML parser (the WebAssembly library: Debian ships
// pugixml as a compiled library only, and nothing else here reads XML as MaterialX does). Every
// document is refused with a located error; reads_materialx() says so beforehand.
#include "matc/material/materialx_import.h"

namespace matc {

MaterialXImport import_materialx(std::string_view, const std::string& path) {
  MaterialXImport result;
  result.diagnostics.error({path, 0, 0}, "",
                           "this build of matc does not read MaterialX documents (it is built "
                           "without pugixml)",
                           "a material file's JSON; or `matc import` it natively first");
  return result;
}

bool materialx_supported() {
  return false;
}

}  // namespace matc
