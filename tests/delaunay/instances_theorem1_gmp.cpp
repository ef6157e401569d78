// One of the shared instantiations of instances.hpp.
#include "instances.hpp"

EXIDEL_TEST_THEOREM1_GMP(template)
