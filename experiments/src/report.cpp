#include "sextant/experiments/report.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "report_overview.hpp"
#include "results_lock.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/log.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/cloud_view.hpp"
#include "sextant/eval/html_report.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/table.hpp"
#include "sextant/experiments/json.hpp"
#include "sextant/experiments/provenance.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/experiments/runner.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;

/// experiment name → its result folders (one per results root that has it).
std::map<std::string, std::vector<fs::path>> find_experiments(const std::vector<fs::path>& roots) {
  std::map<std::string, std::vector<fs::path>> found;
  for (const auto& root : roots) {
    if (!fs::is_directory(root)) throw InputError(root.string(), "", "not a results folder");
    if (fs::exists(root / kEffectiveConfig)) {  // a single experiment's folder given directly
      found[root.filename().string()].push_back(root);
      continue;
    }
    for (const auto& entry : fs::directory_iterator(root)) {
      if (entry.is_directory() && fs::exists(entry.path() / kEffectiveConfig))
        found[entry.path().filename().string()].push_back(entry.path());
    }
  }
  return found;
}

/// Rows of all folders, one per key; a successful row beats a failed one.
/// Unreadable lines are skipped, each named (file:line) in `warnings` and logged. `shared_keys`
/// counts the keys that more than one folder holds.
std::vector<RunRow> union_rows(const std::vector<fs::path>& folders,
                               std::vector<std::string>* warnings = nullptr,
                               std::size_t* shared_keys = nullptr) {
  std::vector<RunRow> rows;
  std::unordered_map<std::string, std::size_t> position;
  std::vector<std::size_t> first_folder;  // per row: the folder it was first found in
  std::vector<bool> shared;               // per row: found in another folder too
  for (std::size_t f = 0; f < folders.size(); ++f) {
    RowFile file = read_rows(folders[f] / kRunsJsonl);
    for (const auto& message : bad_line_messages(folders[f] / kRunsJsonl, file)) {
      log_warning(message);
      if (warnings) warnings->push_back(message);
    }
    for (auto& row : file.rows) {
      const auto it = position.find(row.key);
      if (it == position.end()) {
        position[row.key] = rows.size();
        rows.push_back(std::move(row));
        first_folder.push_back(f);
        shared.push_back(false);
        continue;
      }
      if (first_folder[it->second] != f) shared[it->second] = true;
      if (row.ok || !rows[it->second].ok) rows[it->second] = std::move(row);
    }
  }
  if (shared_keys) *shared_keys = static_cast<std::size_t>(std::count(shared.begin(), shared.end(), true));
  return rows;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<fs::path> provenance_files(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("provenance", 0) == 0 && entry.path().extension() == ".json")
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::string escape(const std::string& s) {
  return escape_html(s);
}

/// "quick" or "full" as the runner recorded it in the folders' provenance ("" when unknown, "mixed" when
/// the folders disagree).
std::string profile_of(const std::vector<fs::path>& folders) {
  std::string profile;
  for (const auto& folder : folders) {
    for (const auto& file : provenance_files(folder)) {
      std::string found;
      try {
        const YAML::Node node = YAML::LoadFile(file.string());
        if (node.IsMap() && node["profile"].IsScalar()) found = node["profile"].Scalar();
      } catch (const YAML::Exception&) {
        continue;  // a provenance file being written or damaged does not decide the profile
      }
      if (found.empty()) continue;
      if (!profile.empty() && profile != found) return "mixed";
      profile = found;
    }
  }
  return profile;
}

/// "Runs: 3 of 4 found; 1 failed (ekf, repetition 2: <error>)." Failed runs are named where users
/// look, never only left out.
std::string runs_line(std::size_t found, std::size_t expected, std::size_t failed,
                      const RunRow* first_failed) {
  std::string line = "Runs: " + std::to_string(found) + " of " + std::to_string(expected) + " found";
  if (failed > 0) {
    line += "; " + std::to_string(failed) + " failed (" + first_failed->method + ", repetition " +
            std::to_string(first_failed->repetition) + ": " + first_failed->error + ")";
  }
  return line + " — missing and failed runs are left out of the statistics.";
}

std::string markdown_section(const std::string& title, const ExperimentConfig& config,
                             const ReportSection& section, const std::string& runs,
                             const std::string& shown) {
  std::string md = "# " + title + "\n\n";
  if (!config.thesis.empty()) md += "Thesis: " + config.thesis + "\n\n";
  if (!config.description.empty()) md += config.description + "\n\n";
  if (!section.notes.empty()) md += section.notes + "\n\n";
  md += runs + "\n\n" + shown + "\n\n";
  for (const auto& table : section.tables) md += render_markdown(table) + "\n";
  for (const auto& scene : section.scenes)
    md += "- [3D view: " + scene.caption + "](" + scene.id + ".html)\n";
  if (!section.scenes.empty()) md += "\n";
  for (const auto& figure : section.figures) md += "![" + figure.caption + "](" + figure.id + ".svg)\n\n";
  for (const auto& t : section.trajectories) md += "- [" + t.caption + "](" + t.id + ".tum) (TUM)\n";
  if (!section.trajectories.empty()) md += "\n";
  if (!section.claims.empty()) {
    md += "## Claims\n\n| claim | verdict | evidence |\n|---|---|---|\n";
    for (const auto& c : section.claims)
      md += "| " + c.statement + " | " + to_string(c.verdict) + " | " + c.evidence + " |\n";
  }
  return md;
}

/// Writes a section's 3D scenes as `<out>/<name>/<id>.html` and links them from the section. The
/// pages share one three.min.js, copied into `out` at the first scene (`three_js` keeps the outcome:
/// empty = copied, else why not; without it the section says so and keeps its static figures).
std::size_t write_scenes(const std::vector<ReportScene>& scenes, const std::string& name, const fs::path& out,
                         std::optional<std::string>& three_js, HtmlSection& html) {
  if (scenes.empty()) return 0;
  if (!three_js) {
    try {
      write_three_js(out);
      three_js = "";
    } catch (const InputError& e) {
      three_js = e.what();
      log_warning("report: no 3D views: " + *three_js);
    }
  }
  if (!three_js->empty()) {
    html.add_paragraph("3D views not written: " + *three_js);
    return 0;
  }
  CloudViewOptions options;
  options.three_js_src = "../three.min.js";
  for (const auto& scene : scenes) {
    write_cloud_view(scene.view, out / name / (scene.id + ".html"), options);
    html.add_view(name + "/" + scene.id + ".html", scene.caption);
  }
  return scenes.size();
}

}  // namespace

ReportSummary write_report(const std::vector<fs::path>& results, const fs::path& out) {
  ReportSummary summary;
  HtmlReport page;
  page.title = "Sextant — reproduction of the thesis' experiments";
  page.subtitle =
      "3D SLAM methods in outdoor and large-scale environments (2012): our numbers beside the thesis'";
  const GitState git = current_git_state();
  page.provenance.push_back({"generated", iso_time_now()});
  page.provenance.push_back({"git", git.sha + (git.dirty ? " (dirty)" : "") + " [" + git.source + "]"});
  page.provenance.push_back({"libraries", library_versions_json()});
  page.provenance.push_back({"host", host_name()});
  std::string roots;
  for (const auto& r : results) roots += (roots.empty() ? "" : ", ") + r.string();
  page.provenance.push_back({"results", roots});

  std::string all_md = "# Sextant report\n\n";
  std::vector<OverviewEntry> overview;
  std::optional<std::string> three_js;  // three.min.js copied for the 3D views: "" = yes, else why not
  for (const auto& [name, folders] : find_experiments(results)) {
    const fs::path config_path = folders.front() / kEffectiveConfig;
    ExperimentConfig config =
        parse_experiment_config(load_yaml_file(config_path.string()), config_path.string(), false);
    // The profile the runs were made with (experiment.yaml already holds the quick overrides).
    for (const auto& file : provenance_files(folders.front()))
      config.quick = config.quick || read_text(file).find("\"profile\": \"quick\"") != std::string::npos;
    const std::string title = config.title.empty() ? name : config.title;
    const std::vector<RunSpec> runs = expand_runs(config);
    OverviewEntry& entry = overview.emplace_back();
    entry.id = name;
    entry.title = title;
    entry.thesis = config.thesis;
    entry.profile = profile_of(folders);
    entry.runs_expected = runs.size();
    std::vector<std::string> warnings;
    const std::vector<RunRow> rows = union_rows(folders, &warnings);
    std::unordered_map<std::string, const RunRow*> by_key, failed_by_key;
    for (const auto& r : rows) (r.ok ? by_key : failed_by_key)[r.key] = &r;
    std::vector<const RunRow*> aligned;
    const RunRow* first_failed = nullptr;
    for (const auto& run : runs) {
      const auto it = by_key.find(run.key);
      aligned.push_back(it == by_key.end() ? nullptr : it->second);
      entry.runs_found += aligned.back() != nullptr;
      const auto failed = failed_by_key.find(run.key);
      if (!aligned.back() && failed != failed_by_key.end()) {
        ++entry.runs_failed;
        if (!first_failed) first_failed = failed->second;
      }
    }
    const std::string runs_text = runs_line(entry.runs_found, runs.size(), entry.runs_failed, first_failed);
    const std::size_t found = entry.runs_found;
    // The heading says which profile the numbers come from and how many runs stand behind them.
    HtmlSection& html = page.add_section(name,
                                         title + " [" + (entry.profile.empty() ? "" : entry.profile + ", ") +
                                             "n = " + std::to_string(found) + " runs]",
                                         title);
    const fs::path dir = out / name;
    fs::create_directories(dir);
    if (!run_kind_registry().contains(config.kind)) {
      entry.failure = "unknown run kind '" + config.kind + "'";
      html.add_paragraph("Unknown run kind '" + config.kind + "': no report for this experiment.");
      continue;
    }
    const auto kind = run_kind_registry().create(config.kind);
    // Which config this section shows, and what of runs.jsonl it leaves out (rows of an earlier,
    // edited config or of the other profile keep their own keys and stay in the file).
    std::unordered_set<std::string> current;
    for (const auto& run : runs) current.insert(run.key);
    std::size_t other = 0;
    for (const auto& r : rows) other += current.count(r.key) == 0;
    std::string shown = "Shown: the config in " + config_path.string() + " (fingerprint " +
                        hex64(stable_hash(canonical_json(config.effective))) + ")";
    if (other > 0) {
      shown +=
          "; " + std::to_string(other) +
          " rows in runs.jsonl belong to another config or profile (edited since, or --quick vs full) and "
          "are kept there but not shown";
    }
    shown += ".";
    for (const auto& w : warnings) shown += " " + w + ".";
    ReportSection section;
    try {
      section = kind->report(config, runs, aligned);
    } catch (const std::exception& e) {
      // One experiment's broken report must not take the others down: say so on the page.
      summary.failed.push_back(name + ": " + e.what());
      entry.failure = e.what();
      html.add_paragraph("The report of this experiment failed: " + std::string(e.what()));
      continue;
    }
    ++summary.experiments;

    if (!config.thesis.empty()) html.add_paragraph("Thesis: " + config.thesis);
    if (!config.description.empty()) html.add_paragraph(config.description);
    if (!section.notes.empty()) html.add_paragraph(section.notes);
    html.add_paragraph(runs_text);
    html.add_paragraph(shown);
    for (const auto& table : section.tables) {
      write_table(table, TableFormat::markdown, dir / (table.label + ".md"));
      write_table(table, TableFormat::latex, dir / (table.label + ".tex"));
      write_table(table, TableFormat::csv, dir / (table.label + ".csv"));
      html.add_table(table);
      html.add_html("<p class=\"files\">Files: <a href=\"" + escape(name + "/" + table.label) +
                    ".md\">Markdown</a> · <a href=\"" + escape(name + "/" + table.label) +
                    ".tex\">LaTeX</a> · <a href=\"" + escape(name + "/" + table.label) +
                    ".csv\">CSV</a></p>");
      ++summary.tables;
    }
    summary.views += write_scenes(section.scenes, name, out, three_js, html);
    for (const auto& figure : section.figures) {
      write_svg(figure.svg, dir / (figure.id + ".svg"));
      html.add_figure(name + "/" + figure.id + ".svg", figure.caption);
      ++summary.figures;
    }
    std::string tum_links;
    for (const auto& t : section.trajectories) {
      write_tum_trajectory(dir / (t.id + ".tum"), t.poses);
      tum_links += std::string(tum_links.empty() ? "" : " · ") + "<a href=\"" + escape(name + "/" + t.id) +
                   ".tum\">" + escape(t.caption) + "</a>";
    }
    if (!tum_links.empty())
      html.add_html("<p class=\"files\">Trajectories (TUM, for evo): " + tum_links + "</p>");
    for (const auto& claim : section.claims) html.add_claim(claim);
    summary.claims += section.claims.size();
    entry.claims = section.claims;

    std::string provenance;
    for (const auto& folder : folders) {
      for (const auto& file : provenance_files(folder)) provenance += read_text(file);
    }
    html.add_html("<details><summary>Provenance</summary><pre>" + escape(provenance) + "</pre></details>");
    const std::string md = markdown_section(title, config, section, runs_text, shown);
    write_file_atomically(dir / (name + ".md"), md);
    all_md += md + "\n";
  }
  std::sort(overview.begin(), overview.end(), [](const OverviewEntry& a, const OverviewEntry& b) {
    const int na = experiment_number(a.id), nb = experiment_number(b.id);
    return na != nb ? (na == 0 ? false : nb == 0 ? true : na < nb) : a.id < b.id;
  });
  page.front_html = overview_html(overview);
  write_file_atomically(out / "overview.md", "# Experiments\n\n" + overview_markdown(overview));
  write_file_atomically(out / "report.md", all_md);
  summary.index_html = out / "index.html";
  page.write(summary.index_html);
  return summary;
}

MergeSummary merge_results(const std::vector<fs::path>& inputs, const fs::path& out) {
  MergeSummary summary;
  for (auto [name, folders] : find_experiments(inputs)) {
    const fs::path dir = out / name;
    const detail::ResultsLock lock(dir);  // no runner and no other merge writes here meanwhile
    // The target's own rows are an input too: a merge never drops what is already there.
    if (fs::exists(dir / kEffectiveConfig)) folders.insert(folders.begin(), dir);
    // The same folder named twice counts once.
    std::vector<fs::path> distinct;
    std::set<fs::path> seen;
    for (const fs::path& f : folders)
      if (seen.insert(fs::weakly_canonical(f)).second) distinct.push_back(f);
    folders = std::move(distinct);
    // Results of two configs are not one experiment: refuse rather than mix them.
    const fs::path config_path = folders.front() / kEffectiveConfig;
    const std::string config_text = read_text(config_path);
    for (const fs::path& f : folders)
      if (read_text(f / kEffectiveConfig) != config_text)
        throw InputError((f / kEffectiveConfig).string(), "",
                         "differs from " + config_path.string() +
                             ": these are results of two configs; merge each config's folders apart");
    const std::vector<RunSpec> runs = expand_runs(
        parse_experiment_config(load_yaml_file(config_path.string()), config_path.string(), false));
    MergedExperiment& merged = summary.experiments.emplace_back();
    merged.name = name;
    merged.inputs = folders.size();
    merged.expected = runs.size();
    // Rows in the expansion order of the config they were run with: the merged files do not depend
    // on how many shards there were or in which order their runs finished.
    const std::vector<RunRow> rows =
        in_expansion_order(union_rows(folders, nullptr, &merged.duplicated), runs);
    std::set<std::string> present;
    for (const RunRow& row : rows)
      if (row.ok) present.insert(row.key);
    for (const RunSpec& run : runs) {
      if (present.count(run.key)) continue;
      ++merged.missing;
      std::string label = run.method;
      for (const auto& [axis, value] : run.point) label += ", " + axis + " = " + value;
      merged.missing_runs.push_back(label + ", repetition " + std::to_string(run.repetition));
    }
    std::string text;
    for (const auto& row : rows) text += to_json_line(row) + "\n";
    write_file_atomically(dir / kRunsJsonl, text);
    write_rows_csv(dir / kRunsCsv, rows);
    write_file_atomically(dir / kEffectiveConfig, config_text);
    std::set<std::string> names;  // provenance files written by this merge
    for (std::size_t k = 0; k < folders.size(); ++k) {
      for (const auto& file : provenance_files(folders[k])) {
        std::string target = file.filename().string();
        if (!names.insert(target).second) {
          target = file.stem().string() + ".input-" + std::to_string(k + 1) + ".json";
          names.insert(target);
        }
        if (fs::weakly_canonical(file) != fs::weakly_canonical(dir / target))
          write_file_atomically(dir / target, read_text(file));
      }
    }
    merged.rows = rows.size();
    summary.rows += rows.size();
  }
  return summary;
}

}  // namespace sextant
