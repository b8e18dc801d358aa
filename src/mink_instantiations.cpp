// mink_instantiations.cpp — the explicit instantiations that <mink/extern_templates.hpp>
// declares `extern` (float and double): compile this file once into a program whose
// other translation units define MINK_EXTERN_TEMPLATES (CMake: link mink::instantiations,
// which does both). Installed as share/mink/mink_instantiations.cpp.
#define MINK_INSTANTIATING
#include "mink/extern_templates.hpp"

MINK_DETAIL_INSTANTIATIONS(, float)
MINK_DETAIL_INSTANTIATIONS(, double)
