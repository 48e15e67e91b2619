// SPDX-License-Identifier: MIT
// seamless: crack-free tessellation, watertightness checks and interval ray
// tracing of B-spline surfaces. Exit status: 0 ok, 1 defects found (check),
// 2 bad input or usage.
#include "commands.h"

#include <seamless/base/error.h>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
    CLI::App app{"seamless: B-spline surfaces to crack-free triangle meshes, watertightness "
                 "checks and interval ray tracing (W. Enger, The Visual Computer 1992)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "seamless 0.1.0");
    seamless::cli::Action action;
    seamless::cli::add_info(app, action);
    seamless::cli::add_tessellate(app, action);
    seamless::cli::add_convert(app, action);
    seamless::cli::add_check(app, action);
    seamless::cli::add_render(app, action);
    seamless::cli::add_sweep(app, action);
    seamless::cli::add_batch(app, action);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        // One line, as for bad input (CLI11's own exit() adds a second).
        // `seamless bogus`: CLI11 says only that a subcommand is required.
        if (app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-') {
            std::string names;
            for (const CLI::App* c : app.get_subcommands({}))
                names += (names.empty() ? "" : ", ") + c->get_name();
            std::cerr << "error: unknown command '" << seamless::printable(argv[1])
                      << "' (expected one of " << names << "; --help for usage)\n";
            return 2;
        }
        std::cerr << "error: " << seamless::printable(e.what()) << " (--help for usage)\n";
        return 2;
    }
    try {
        return action ? action() : 0;
    } catch (const seamless::InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        std::cerr << "error: out of memory\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "error: " << seamless::printable(e.what()) << "\n";
        return 2;
    }
}
