/* Tests of the microsurface module (to be filled in). */
#include "mf_test.h"

void test_microsurface(void)
{
}
