#include "algorithms/algorithm_registry.hpp"

namespace mhb {

// One line per optimiser; each is defined in its own file.
void register_itlbo(AlgorithmRegistry& registry);
void register_tlbo(AlgorithmRegistry& registry);
void register_pso(AlgorithmRegistry& registry);
void register_spso2011(AlgorithmRegistry& registry);
void register_de(AlgorithmRegistry& registry);
void register_lshade(AlgorithmRegistry& registry);
void register_jso(AlgorithmRegistry& registry);
void register_nl_shade_lbc(AlgorithmRegistry& registry);
void register_lshade_cnepsin(AlgorithmRegistry& registry);
void register_cmaes(AlgorithmRegistry& registry);
void register_etlbo(AlgorithmRegistry& registry);
void register_jaya(AlgorithmRegistry& registry);
void register_nlopt(AlgorithmRegistry& registry);
void register_random_search(AlgorithmRegistry& registry);
void register_external_optimizer(AlgorithmRegistry& registry);

void register_builtin_algorithms(AlgorithmRegistry& registry) {
    register_itlbo(registry);
    register_tlbo(registry);
    register_pso(registry);
    register_spso2011(registry);
    register_de(registry);
    register_lshade(registry);
    register_jso(registry);
    register_nl_shade_lbc(registry);
    register_lshade_cnepsin(registry);
    register_cmaes(registry);
    register_etlbo(registry);
    register_jaya(registry);
    register_nlopt(registry);
    register_random_search(registry);
    register_external_optimizer(registry);
}

const AlgorithmRegistry& builtin_algorithms() {
    static const AlgorithmRegistry registry = [] {
        AlgorithmRegistry r("algorithm");
        register_builtin_algorithms(r);
        return r;
    }();
    return registry;
}

} // namespace mhb
