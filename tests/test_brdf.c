#include "mf_test.h"
void test_brdf(void) {}
