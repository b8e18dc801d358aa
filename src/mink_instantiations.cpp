// mink_instantiations.cpp — the explicit instantiations that mink's headers declare
// `extern` under MINK_EXTERN_TEMPLATES (float and double; the list is
// include/mink/core/detail/instantiation_lists.hpp): compile this file once into a
// program whose other translation units define MINK_EXTERN_TEMPLATES (CMake: link
// mink::instantiations, which does both). Installed as share/mink/mink_instantiations.cpp.
#define MINK_INSTANTIATING
#include "mink/extern_templates.hpp"

MINK_DETAIL_INSTANTIATIONS(, float)
MINK_DETAIL_INSTANTIATIONS(, double)
