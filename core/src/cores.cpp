#include "holefill/cores.h"

#include "available_cores.h"

namespace holefill {

unsigned available_cores() { return detail::available_cores(); }

}  // namespace holefill
