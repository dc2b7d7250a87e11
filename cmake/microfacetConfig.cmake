# find_package(microfacet): defines the INTERFACE target microfacet::microfacet.
include("${CMAKE_CURRENT_LIST_DIR}/microfacetTargets.cmake")
