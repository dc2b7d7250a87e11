#include "mf_test.h"
void test_float(void) {}
