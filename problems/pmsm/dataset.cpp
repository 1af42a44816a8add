#include "problems/pmsm/dataset.hpp"

#include "problems/core/parameters.hpp"

namespace mhb::pmsm {

void Dataset::reserve(std::size_t n) {
    t.reserve(n);
    ud.reserve(n);
    uq.reserve(n);
    id.reserve(n);
    iq.reserve(n);
    omega.reserve(n);
    injected.reserve(n);
}

void Dataset::push_back(double t_k, double ud_k, double uq_k, double id_k, double iq_k, double omega_k,
                        bool injected_k) {
    t.push_back(t_k);
    ud.push_back(ud_k);
    uq.push_back(uq_k);
    id.push_back(id_k);
    iq.push_back(iq_k);
    omega.push_back(omega_k);
    injected.push_back(injected_k);
}

const std::string* Dataset::find_metadata(const std::string& key) const {
    for (const auto& [k, v] : metadata)
        if (k == key)
            return &v;
    return nullptr;
}

void Dataset::set_metadata(const std::string& key, std::string value) {
    for (auto& [k, v] : metadata)
        if (k == key) {
            v = std::move(value);
            return;
        }
    metadata.emplace_back(key, std::move(value));
}

void Dataset::set_metadata(const std::string& key, double value) {
    set_metadata(key, format_real(value));
}

std::optional<Eigen::Vector4d> Dataset::true_parameters() const {
    Eigen::Vector4d out;
    const char* keys[] = {"Rs", "Ld", "Lq", "psi"};
    for (int i = 0; i < 4; ++i) {
        const std::string* v = find_metadata(keys[i]);
        double x = 0;
        if (v == nullptr || !parse_real(*v, x))
            return std::nullopt;
        out[i] = x;
    }
    return out;
}

std::pair<std::size_t, std::size_t> Dataset::state_counts() const {
    std::size_t on = 0;
    for (const bool b : injected)
        on += b ? 1 : 0;
    return {injected.size() - on, on};
}

} // namespace mhb::pmsm
