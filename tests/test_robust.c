#include "mf_test.h"
void test_robust(void) {}
