#pragma once
// The commands every program of cli::run has (cli/app.hpp), over the models of a
// catalogue. Each returns the process exit code (exit_status.hpp) and throws
// catalogue::UsageError or tioa::ModelError on bad input.

#include <string>
#include <vector>

#include "catalogue/registry.hpp"
#include "cli/settings.hpp"

namespace cli {

// Every model with its description, parameters and properties.
int command_list(const catalogue::Catalogue& models, bool json);

// The model's properties (or the requested ones) on the instance the parameters build.
int command_check(const catalogue::Catalogue& models, const ModelRequest& request,
                  const RunSettings& settings);

// Counterexample search: the model's invariants and a deadlock / time-lock check, from
// arbitrary states (`from` = "arbitrary": U(A)) or from the model's start states ("start").
int command_explore(const catalogue::Catalogue& models, const ModelRequest& request,
                    const std::string& from, const RunSettings& settings);

// Every suite entry of every model against its expected verdict.
// `only`: the models whose entries run (empty: every model).
int command_suite(const catalogue::Catalogue& models, const RunSettings& settings,
                  const std::vector<std::string>& only = {});

} // namespace cli
