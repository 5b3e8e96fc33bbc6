// `glintlab dict`: generates the chermain2020 dictionary (004 §4.4-4.5) with
// the given parameters and writes it to a file (format in dictionary.h).
#include <fmt/format.h>

#include "commands.h"
#include "glintlab/glints/chermain2020/dictionary.h"

namespace glintlab::cmd {

void add_dict_command(CLI::App& app, int* status) {
    CLI::App* sub = app.add_subcommand(
        "dict", "Generate the chermain2020 dictionary of multiscale marginal SDFs");
    struct Args {
        std::string output = "chermain2020_dict.bin";
        DictionaryParams p;
    };
    auto args = std::make_shared<Args>();
    sub->add_option("-o,--output", args->output, "output file")->capture_default_str();
    sub->add_option("--levels", args->p.n_levels, "nLevels, levels of detail")
        ->check(CLI::Range(1, 20))
        ->capture_default_str();
    sub->add_option("--dists", args->p.n_dists, "N, marginal distributions")
        ->check(CLI::Range(1, 4096))
        ->capture_default_str();
    sub->add_option("--alpha", args->p.alpha_dict, "alpha_dict, Beckmann roughness of the target")
        ->check(FiniteRange(0.01, 2.0))
        ->capture_default_str();
    sub->add_option("--lobe-sigma", args->p.lobe_sigma, "std-dev of each Gaussian lobe, <= alpha/2")
        ->check(FiniteRange(1e-4, 1.0))
        ->capture_default_str();
    sub->add_option("--samples", args->p.table_size, "samples per 1-D table")
        ->check(CLI::Range(4, 4096))
        ->capture_default_str();
    sub->add_option("--seed", args->p.seed, "seed of the lobe means")->capture_default_str();
    sub->callback([args, status] {
        const Dictionary d = generate_dictionary(args->p);  // checks the remaining ranges
        write_dictionary(d, args->output);
        const DictionaryParams& p = d.params;
        fmt::print(
            "{}: nLevels {}, N {}, alpha_dict {}, lobe sigma {}, {} samples over |x| < {:.6g}, "
            "seed {}, {} floats ({} bytes)\n",
            args->output, p.n_levels, p.n_dists, p.alpha_dict, p.lobe_sigma, p.table_size,
            d.slope_max, p.seed, d.values.size(), d.values.size() * sizeof(float) + 40);
        *status = 0;
    });
}

}  // namespace glintlab::cmd
