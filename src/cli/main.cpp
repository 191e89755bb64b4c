// tstyles: one executable, several subcommands. Turns every error into one message and an exit code.
#include <iostream>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "manual_page.h"
#include "packaging_files.h"
#include "version_text.h"
#include "tstyles/core/errors.h"
#include "tstyles/distributed/mpi_session.h"

int main(int argc, char** argv) {
    using namespace tstyles;
    CLI::App app{"Temporal Styles: time-varying volume rendering with temporal style transfer functions"};
    app.require_subcommand(1);
    app.set_version_flag("--version", [] { return cli::versionText(); },
                         "Print the version, the OpenGL renderer `render` would use and where the bundled data is");
    const std::vector<cli::Command> commands = {cli::addRenderCommand(app), cli::addInfoCommand(app),
                                                cli::addProbeCommand(app), cli::addBenchCommand(app), cli::addViewCommand(app),
                                                cli::addConvertCommand(app), cli::addSceneCommand(app),
                                                cli::addAnimateCommand(app), cli::addCompareCommand(app),
                                                cli::addCheckCommand(app), cli::addManualPageCommand(app),
                                                cli::addPackagingFileCommand(app)};
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int code = app.exit(error);
        return code == 0 ? cli::kExitSuccess : cli::kExitBadInput;
    }
    try {
        for (const auto& command : commands)
            if (command.parsed->parsed()) return command.run();
    } catch (const FailedOnAnotherProcess&) {
        // Process 0 of the MPI run says why and exits with the code; mpirun passes it on. A non-zero
        // exit here would make mpirun stop the job, process 0 too, perhaps before it has printed.
        return cli::kExitSuccess;
    } catch (const InputError& error) {
        std::cerr << "tstyles: " << error.what() << "\n";
        return cli::kExitBadInput;
    } catch (const GlUnavailableError& error) {
        std::cerr << "tstyles: " << error.what() << "\n";
        return cli::kExitNoOpenGl;
    } catch (const std::exception& error) {
        std::cerr << "tstyles: internal error: " << error.what() << "\n";
        return cli::kExitFailure;
    }
    return cli::kExitFailure;
}
