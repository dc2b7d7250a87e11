/* An implementation unit for the link-mixing checks (tests/config_check.sh). */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
