/* Tests of the tabulated module (to be filled in). */
#include "mf_test.h"

void test_tabulated(void)
{
}
