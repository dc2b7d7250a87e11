/* The implementation, compiled once and linked into every fuzz target. */
#define MICROFACET_IMPLEMENTATION
#include "microfacet.h"
