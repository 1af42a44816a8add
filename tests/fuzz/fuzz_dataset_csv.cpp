// Fuzzes the PMSM dataset CSV reader (problems/pmsm/dataset_csv.hpp): any bytes either read as a
// dataset or give std::runtime_error. What reads must also survive a write and a second read bit for
// bit, as write_dataset_csv promises.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "problems/pmsm/dataset_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    mhb::pmsm::Dataset dataset;
    try {
        dataset = mhb::pmsm::read_dataset_csv(in, "fuzz.csv");
    } catch (const std::runtime_error&) {
        return 0;
    }
    std::ostringstream out;
    mhb::pmsm::write_dataset_csv(out, dataset);
    std::istringstream again(out.str());
    const mhb::pmsm::Dataset copy = mhb::pmsm::read_dataset_csv(again, "fuzz.csv (written back)");
    if (copy.t != dataset.t || copy.ud != dataset.ud || copy.uq != dataset.uq || copy.id != dataset.id ||
        copy.iq != dataset.iq || copy.omega != dataset.omega || copy.injected != dataset.injected ||
        copy.metadata != dataset.metadata)
        std::abort(); // write + read must reproduce the dataset
    return 0;
}
