#include "problems/problem_registry.hpp"

namespace mhb {

// One line per problem family (or set of families); each is defined in its own file.
void register_classic_functions(ProblemRegistry& registry);
void register_f0(ProblemRegistry& registry);
void register_bbob(ProblemRegistry& registry);
void register_pmsm(ProblemRegistry& registry);
void register_cec(ProblemRegistry& registry);
void register_fluxmap(ProblemRegistry& registry);
void register_external_problem(ProblemRegistry& registry);

void register_builtin_problems(ProblemRegistry& registry) {
    register_classic_functions(registry);
    register_f0(registry);
    register_bbob(registry);
    register_pmsm(registry);
    register_cec(registry);
    register_fluxmap(registry);
    register_external_problem(registry);
}

const ProblemRegistry& builtin_problems() {
    static const ProblemRegistry registry = [] {
        ProblemRegistry r("problem");
        register_builtin_problems(r);
        return r;
    }();
    return registry;
}

} // namespace mhb
