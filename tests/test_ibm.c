/* Tests of the ibm module (to be filled in). */
#include "mf_test.h"

void test_ibm(void)
{
}
