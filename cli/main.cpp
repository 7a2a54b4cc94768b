// cutcom: what a SINUMERIK 840D would do with an NC program under 2D tool radius compensation.
// Exit status: 0 done without alarm, 1 an alarm stopped the program, 2 bad input or usage.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>

#include "commands.hpp"

using namespace cutcom::cli;

namespace {
// CLI11's NonNegativeNumber names the largest double in its message; this one says what is meant.
const CLI::Validator kNotNegative(
    [](std::string& v) {
      double d = 0;
      return CLI::detail::lexical_cast(v, d) && d >= 0 ? std::string() : "'" + v + "' is not a number of 0 or more";
    },
    "0 or more");
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"cutcom: SINUMERIK 840D 2D tool radius compensation, exact reference and fast engine"};
  app.require_subcommand(1);
  RunOptions o;
  auto* run = app.add_subcommand("run", "compute the tool-centre path of an NC program");
  run->add_option("PROGRAM", o.program, "NC program file, - for standard input")->required();
  run->add_option("--engine", o.engine, "ref (exact) or fast (double)")->check(CLI::IsMember({"ref", "fast"}));
  run->add_option("--format", o.format, "text, json or svg")->check(CLI::IsMember({"text", "json", "svg"}));
  run->add_option("-o,--output", o.output, "write to FILE instead of standard output");
  run->add_option("--md", o.md, "machine datum NAME=VALUE, e.g. --md MD20204=0.02 (repeatable)");
  run->add_option("--md-file", o.md_files, "file of NAME=VALUE lines (repeatable)");
  run->add_option("--sysvar", o.system_values,
                  "a system variable the program reads that cutcom does not model, $NAME[index]=VALUE (a number or "
                  "\"text\"), e.g. --sysvar '$A_IN[1]=1' (repeatable)");
  run->add_flag("--trace", o.trace, "include the decision trace (text and json)");
  run->add_flag("--stage-times", o.stage_times,
                "print on standard error the processor time of each thread (the reader and the engine share one, the "
                "writer has its own) and the run's elapsed time");
  run->add_option("--tools", o.tool_files,
                  "tool-offset archive ($TC_DPn[t,d]=..., $TC_TP2[t]=\"NAME\" lines, TO_INI.INI style; repeatable)");
  run->add_option("--tool", o.tool_edges,
                  "one tool edge TOOL[/EDGE]=RADIUS, TOOL a number or a name: --tool 1=5 --tool \"FLAT 10\"/2=4.98 "
                  "(an end mill); RADIUS,POSITION a turning tool with that cutting edge position: --tool 2=0.4,3 "
                  "(after --tools, repeatable)");
  run->add_option("--offsets", o.offsets_file, "settable work offsets ($P_UIFR[n]=CTRANS(X,..,Y,..) lines)");
  run->add_option("--channel", o.channel,
                  "the channel that runs the program: its data are read from archives (--tools, --offsets, "
                  "--md-file) that hold several channels' (CHANDATA(n))")
      ->check(CLI::Range(1, 99));
  run->add_option("--skip", o.skip_levels,
                  "skip level switched on: blocks marked /LEVEL (/ is /0) are left out, as with the control's "
                  "skip switch (0-9, repeatable; default: all off, skip blocks run)")
      ->check(CLI::Range(0, 9));
  run->add_option("--max-loops", o.max_loops,
                  "loop passes and backward jumps before a program counts as running away (NC-PARAM-FLOW-6)")
      ->check(CLI::PositiveNumber);
  run->add_option("--definitions", o.definition_files,
                  "global user data: a file of DEF lines (GUD, DEF.DIR/*.DEF) every program level sees (repeatable)");
  run->add_option("--args", o.arguments,
                  "run PROGRAM, a subprogram, on its own with these arguments, e.g. --args \"40, 2.5, , 1\"");
  run->add_option("--search-path", o.search_path,
                  "folder where subprograms (NAME.SPF) are looked for after the program's own (repeatable)")
      ->check(CLI::ExistingDirectory);
  run->add_option("--machine-cycle", o.machine_cycles,
                  "a cycle or subprogram of the machine itself (a tool change L6, TC, ...) that is not in the "
                  "program's folder: its calls are not simulated, as standard cycles (repeatable)");
  RunOptions mo;  // the machine data options of `run`, for `md`
  auto* md = app.add_subcommand("md", "list the machine data, their values and ranges");
  md->add_option("--md", mo.md, "override NAME=VALUE before listing");
  md->add_option("--md-file", mo.md_files, "file of NAME=VALUE lines, read before --md (repeatable)");
  md->add_option("--channel", mo.channel, "the channel whose data an archive of several gives")
      ->check(CLI::Range(1, 99));
  auto* alarms = app.add_subcommand("alarms", "list the alarm catalogue");
  CertifyOptions co;
  auto* certify =
      app.add_subcommand("certify", "certify fast against ref on generated programs (docs/certification.md)");
  certify->add_option("--cases", co.campaign.cases, "cases in this shard (0: until --time)")->check(kNotNegative);
  certify->add_option("--time", co.campaign.seconds, "stop after this many seconds")->check(kNotNegative);
  certify
      ->add_option("--budget", co.campaign.budget,
                   "seconds one case may take (default 60; 0: no limit, all in this process); a case over "
                   "budget is recorded as over-budget, not compared")
      ->check(kNotNegative);
  certify->add_option("--seed", co.campaign.seed, "campaign seed (case k is the same program in any sharding)");
  certify->add_option("--shard", co.shard, "I/N: run cases k = I, I+N, I+2N, ... of the campaign");
  certify
      ->add_option("--jobs", co.jobs,
                   "run the cases in N processes on this machine and merge them (default: one per core)")
      ->check(CLI::Range(1, 1024));
  certify->add_option("--results", co.campaign.results, "JSON lines, one per case");
  certify->add_option("--corpus", co.campaign.corpus, "directory for an unexplained divergence (tests/corpus)");
  certify->add_option("--summary", co.summary, "write the shard's summary (JSON) for --merge");
  certify->add_option("--merge", co.merge, "merge shard summaries instead of running")->expected(1, -1);
  certify->add_option("--report", co.report, "write the report (docs/certification.md) and its error histogram");
  certify->add_option("--histogram", co.histogram, "the histogram's SVG file (next to the report by default)");
  certify->add_option("--spec", co.spec, "spec directory, for the clause list of the coverage table");
  certify->add_flag("!--no-progress", co.campaign.progress, "no progress bar");
  certify->add_option("--knife-baseline", co.knife_baseline,
                      "fail when a clause's knife edges rise beyond noise over this baseline (JSON)");
  certify->add_option("--write-knife-baseline", co.write_knife_baseline,
                      "write this campaign's knife edges per clause as a baseline (JSON)");
  certify->add_option("--replay", co.replay, "judge these programs (FILE.md beside each: machine data) and stop")
      ->expected(1, -1);
  certify
      ->add_option("--from", co.from,
                   "certify fast on these programs (FILE.md beside each: machine data) and their neighbours")
      ->expected(1, -1);
  certify->add_option("--neighbours", co.neighbours, "--from: neighbours of each program (default 200)")
      ->check(CLI::Range(0L, 10'000'000L));
  certify->add_option("--show", co.show, "print the program of campaign case K (with --seed) and stop")
      ->check(kNotNegative);
  // TOOL-FILE-1/2, NC-OFFSET-2, NC-PARAM-VAR-3, NC-PARAM-SUB-1: a user's programs need the control's data.
  certify->add_option("--tools", co.control.tool_files, "--replay/--from: tool-offset archive (as for run)");
  certify->add_option("--tool", co.control.tool_edges,
                      "--replay/--from: one tool edge TOOL[/EDGE]=RADIUS (as for run)");
  certify->add_option("--offsets", co.control.offsets_file, "--replay/--from: settable work offsets (as for run)");
  certify->add_option("--definitions", co.control.definition_files, "--replay/--from: global user data (as for run)");
  certify
      ->add_option("--search-path", co.control.search_path,
                   "--replay/--from: folder where subprograms are looked for after the program's own")
      ->check(CLI::ExistingDirectory);
  certify->add_option("--machine-cycle", co.control.machine_cycles,
                      "--replay/--from: a cycle of the machine, not simulated (as for run)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }
  try {
    if (*run) return run_command(o);
    if (*md) return list_machine_data(mo);
    if (*alarms) return list_alarms();
    if (*certify) return certify_command(co);
  } catch (const cutcom::InputError& e) {
    std::cout.flush();
    std::cerr << fmt::format("cutcom: {}: {}\n", o.program, e.what());
    return kBadInput;
  } catch (const cutcom::MachineDataError& e) {
    std::cerr << fmt::format("cutcom: machine data: {}\n", e.what());
    return kBadInput;
  } catch (const FileError& e) {
    std::cerr << fmt::format("cutcom: {}\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << fmt::format("cutcom: internal error: {}\n", e.what());
    return 3;
  }
  return kBadInput;
}
