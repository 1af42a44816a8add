// Registration of the `fluxmap` problem family: fitting a current map (SyRM, Hinkkanen et al.
// 2017; PM-SyRM, Lelli et al. 2024; current_map.hpp) to a flux map by least squares, in A^2.
// The data are the shipped Baldor map (default; f* and theta* known, data/README.md), a user's
// CSV (`data=map.csv`), or a synthetic map with a known truth (`synthetic=on`, synthetic_map.hpp).
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "problems/core/bound_text.hpp"
#include "problems/fluxmap/baldor_optimum.hpp"
#include "problems/fluxmap/current_map.hpp"
#include "problems/fluxmap/synthetic_map.hpp"
#include "problems/problem_registry.hpp"

namespace mhb::fluxmap {
namespace {

class FluxMapProblem final : public Problem {
public:
    FluxMapProblem(CurrentMap map, Box box) : map_(std::move(map)), box_(std::move(box)) {}

    [[nodiscard]] std::string name() const override { return "fluxmap"; }
    [[nodiscard]] Eigen::Index dimension() const override { return box_.dimension(); }
    [[nodiscard]] const Box& bounds() const override { return box_; }
    [[nodiscard]] double evaluate(const Eigen::VectorXd& x) const override { return map_.sum_of_squares(x); }
    [[nodiscard]] std::optional<KnownOptimum> known_optimum() const override { return optimum_; }
    [[nodiscard]] std::vector<std::string> parameter_names() const override {
        return fluxmap::parameter_names(map_.model());
    }
    [[nodiscard]] std::optional<Eigen::VectorXd> true_parameters() const override { return truth_; }
    [[nodiscard]] std::vector<DataFile> data_files() const override { return files_; }
    [[nodiscard]] std::vector<std::string> warnings() const override { return warnings_; }

    std::optional<KnownOptimum> optimum_;
    std::optional<Eigen::VectorXd> truth_;
    std::vector<DataFile> files_;
    std::vector<std::string> warnings_;

private:
    CurrentMap map_;
    Box box_;
};

// The default search box (see the family's help): wide enough for the published values and the
// least-squares optimum of the Baldor map; the exponents start at 0 or 0.5, never below 0.
Box default_box(Model model) {
    Box box;
    box.lower.resize(parameter_count(model));
    box.upper.resize(box.lower.size());
    const double lo[] = {0, 0, 0, 0, 0, 0.5, 0.5, 0, 0, 0.3, 0, 0, 0.5, 0};
    const double hi[] = {20, 200, 20, 50, 300, 10, 10, 5, 5, 1.2, 500, 20, 6, 1};
    for (Eigen::Index j = 0; j < box.lower.size(); ++j)
        box.lower[j] = lo[j], box.upper[j] = hi[j];
    return box;
}

Box search_box(const ParameterValues& p, Model model) {
    Box box = default_box(model);
    const auto names = parameter_names(Model::pmsyrm);
    const auto exponents = exponent_indices(model);
    for (Eigen::Index j = 0; j < static_cast<Eigen::Index>(names.size()); ++j) {
        const std::string& key = names[static_cast<std::size_t>(j)];
        if (!p.given(key))
            continue;
        if (j >= box.dimension())
            throw std::invalid_argument("fluxmap: '" + key + "' is a parameter of model=pmsyrm, not syrm");
        parse_bound_text("fluxmap", key, p.text(key), "0:5", box.lower[j], box.upper[j]);
        const bool exponent = std::find(exponents.begin(), exponents.end(), j) != exponents.end();
        if ((exponent || key == "k_q") && box.lower[j] < 0)
            throw std::invalid_argument("fluxmap: parameter '" + key + "' = " + p.text(key) +
                                        " needs lo >= 0 (" +
                                        (exponent ? "a negative power of a zero flux linkage is infinite"
                                                  : "k_q psi_q^2 is under a square root") +
                                        ")");
    }
    return box;
}

// `truth=v1/v2/...`: one value per parameter of the model, in its order.
Eigen::VectorXd parse_truth(const std::string& text, Model model) {
    const Eigen::Index n = parameter_count(model);
    std::vector<double> values;
    std::size_t start = 0;
    while (start <= text.size()) {
        const auto slash = text.find('/', start);
        const std::string piece = text.substr(start, slash == std::string::npos ? slash : slash - start);
        double v = 0;
        if (!parse_real(piece, v))
            throw std::invalid_argument("fluxmap: parameter 'truth' = " + text + ": '" + piece +
                                        "' is not a finite number");
        values.push_back(v);
        if (slash == std::string::npos)
            break;
        start = slash + 1;
    }
    if (static_cast<Eigen::Index>(values.size()) != n)
        throw std::invalid_argument("fluxmap: parameter 'truth' = " + text + " has " +
                                    std::to_string(values.size()) +
                                    " values; model=" + (model == Model::syrm ? "syrm" : "pmsyrm") + " has " +
                                    std::to_string(n) + " parameters, written v1/v2/...");
    return Eigen::Map<const Eigen::VectorXd>(values.data(), n);
}

std::unique_ptr<Problem> make_fluxmap(const ParameterValues& p) {
    const Model model = p.text("model") == "syrm" ? Model::syrm : Model::pmsyrm;
    const bool synthetic = p.boolean("synthetic");
    if (synthetic && p.given("data"))
        throw std::invalid_argument("fluxmap: give either 'data' (a measured map) or synthetic=on, not both");
    if (!synthetic)
        for (const char* key : {"truth", "noise", "seed"})
            if (p.given(key))
                throw std::invalid_argument(std::string("fluxmap: '") + key +
                                            "' applies to synthetic=on only");
    Box box = search_box(p, model);
    const Eigen::Index n = parameter_count(model);
    std::vector<DataFile> files;
    std::optional<Eigen::VectorXd> truth;
    FluxMap data;
    if (synthetic) {
        truth = p.given("truth") ? parse_truth(p.text("truth"), model)
                                 : Eigen::VectorXd(published_values().head(n));
        if (!box.contains(*truth))
            throw std::invalid_argument("fluxmap: the truth lies outside the search box");
        data = synthetic_map(model, *truth, p.real("noise"), static_cast<std::uint64_t>(p.integer("seed")));
    } else if (p.given("data")) {
        DataFile file{p.text("data"), ""};
        data = read_flux_map_csv(file.path, n, &file.sha256);
        files.push_back(std::move(file));
    } else {
        data = baldor_flux_map();
    }
    auto problem = std::make_unique<FluxMapProblem>(CurrentMap(model, std::move(data)), std::move(box));
    if (synthetic && p.real("noise") == 0.0)
        problem->optimum_ = KnownOptimum{0.0, *truth};
    if (!synthetic && !p.given("data")) {
        const KnownOptimum best = baldor_optimum(model);
        if (problem->bounds().contains(*best.x))
            problem->optimum_ = best;
        if (model == Model::syrm)
            problem->warnings_.push_back(
                "fluxmap: the best-known SyRM optimum of the Baldor map has a_d0 = 0, on "
                "its lower bound (SyRM has no magnet term for this PM machine)");
    }
    problem->truth_ = truth;
    problem->files_ = std::move(files);
    return problem;
}

std::vector<ParameterInfo> bound_parameters() {
    const Box box = default_box(Model::pmsyrm);
    const auto names = parameter_names(Model::pmsyrm);
    std::vector<ParameterInfo> out;
    for (std::size_t j = 0; j < names.size(); ++j) {
        const auto i = static_cast<Eigen::Index>(j);
        out.push_back(ParameterInfo::text(names[j], "",
                                          "search bounds of " + names[j] + ", lo:hi (default " +
                                              format_real(box.lower[i]) + ":" + format_real(box.upper[i]) +
                                              (j >= 9 ? "; pmsyrm only)" : ")")));
    }
    return out;
}

} // namespace
} // namespace mhb::fluxmap

namespace mhb {

void register_fluxmap(ProblemRegistry& registry) {
    std::vector<ParameterInfo> parameters = {
        ParameterInfo::choice(
            "model", "pmsyrm", {"syrm", "pmsyrm"},
            "syrm: 9 parameters (Hinkkanen et al. 2017); pmsyrm: those and psi_n a_b a_bp W "
            "k_q, a saturating bridge beside the magnet (Lelli et al. 2024)"),
        ParameterInfo::text("data", "",
                            "a flux-map CSV (columns i_d,i_q,psi_d,psi_q in A and V s); default: the shipped "
                            "Baldor ECS101M0H7EF4 map at 400 rpm (567 points, MIT, best-known f* known)"),
        ParameterInfo::boolean("synthetic", false,
                               "fit a synthetic map: currents of the model at 'truth' on a 21 x 27 grid of "
                               "psi_d, psi_q spanning the Baldor map, plus Gaussian noise"),
        ParameterInfo::text(
            "truth", "",
            "synthetic: the true parameters v1/v2/... in the model's order (default: motulator's "
            "published values for the Baldor machine)"),
        ParameterInfo::real("noise", 0.0, 0.0, 1e3, "synthetic: current noise (std) added to i_d and i_q, A"),
        ParameterInfo::integer("seed", 1, 0, 9007199254740992LL, "synthetic: seed of the noise"),
    };
    for (auto& bound : fluxmap::bound_parameters())
        parameters.push_back(std::move(bound));
    registry.add(
        {"fluxmap", 1,
         "current map (SyRM or PM-SyRM saturation model) fitted to a measured flux map: sum of "
         "squared current errors, A^2",
         "Hinkkanen et al. (2017), IEEE Trans. Ind. Appl. 53(3), doi 10.1109/TIA.2016.2644624; "
         "Lelli, Hinkkanen and Giulii Capponi (2024), Proc. ICEM, doi 10.1109/ICEM60801.2024.10700403",
         std::move(parameters), fluxmap::make_fluxmap});
}

} // namespace mhb
