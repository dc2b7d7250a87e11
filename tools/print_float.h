/* print_float.h - shared by the table generators (tools/ltc_fit.c,
 * tools/energy_fit.c): prints a double as a C float literal. */
#include <stdio.h>
#include <string.h>

/* a float literal: %.6g with a decimal point or exponent, and the f suffix */
static void print_float(double v)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.6g", v);
    if (!strpbrk(buf, ".e")) strcat(buf, ".0");
    else if (!strchr(buf, '.')) { char *e = strchr(buf, 'e'); memmove(e + 2, e, strlen(e) + 1); e[0] = '.'; e[1] = '0'; }
    printf("%sf,", buf);
}
