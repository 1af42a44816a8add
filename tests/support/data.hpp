// Where the tests' data files are (tests/data/, MHB_TEST_DATA_DIR), by folder.
#pragma once

#include <string>

namespace mhb::test_support {

// tests/data/pmsm/, with the trailing slash: the PMSM datasets and reference outputs.
inline const std::string pmsm_data_dir = std::string(MHB_TEST_DATA_DIR) + "/pmsm/";

} // namespace mhb::test_support
