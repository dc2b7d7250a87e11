/* The test modules, one line each in run order: test_<name> in
 * tests/test_<name>.c (the Makefile reads this list too; adding a module is
 * one line here). MFT_QUICK: also in `make check` and in the C++ builds of
 * `make test` (the runner's --quick). */
MFT_QUICK(test_core)
MFT_MODULE(test_ndf)
MFT_MODULE(test_sampling)
MFT_MODULE(test_brdf)
MFT_MODULE(test_ltmd)
MFT_MODULE(test_ltc)
MFT_MODULE(test_ltc_shapes)
MFT_QUICK(test_leadr)
MFT_QUICK(test_tabulated)
MFT_MODULE(test_ibm)
MFT_MODULE(test_microsurface)
MFT_MODULE(test_materials)
MFT_MODULE(test_dielectric)
MFT_MODULE(test_energy)
MFT_MODULE(test_lobes)
MFT_QUICK(test_robust)
MFT_MODULE(test_samplers)
MFT_MODULE(test_fuzzfound)
MFT_QUICK(test_float)
MFT_QUICK(test_tu2)
