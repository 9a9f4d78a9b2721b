#include "sextant/experiments/report.hpp"

#include <algorithm>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "report_causes.hpp"
#include "report_overview.hpp"
#include "result_folders.hpp"
#include "sextant/core/atomic_file.hpp"
#include "sextant/core/error.hpp"
#include "sextant/core/io/trajectory_io.hpp"
#include "sextant/core/log.hpp"
#include "sextant/core/output_folder.hpp"
#include "sextant/core/settings_reader.hpp"
#include "sextant/eval/cloud_view.hpp"
#include "sextant/eval/html_report.hpp"
#include "sextant/eval/plots.hpp"
#include "sextant/eval/table.hpp"
#include "sextant/experiments/run_kind.hpp"
#include "sextant/experiments/runner.hpp"
#include "sextant/pipeline/json.hpp"
#include "sextant/pipeline/provenance.hpp"
#include "sextant/pipeline/yaml_json.hpp"

namespace sextant {
namespace {

namespace fs = std::filesystem;
using detail::find_experiments;
using detail::provenance_files;
using detail::read_text;
using detail::union_rows;

std::string escape(const std::string& s) {
  return escape_html(s);
}

/// The "profile" a provenance file records; "" when it has none or cannot be read.
std::string recorded_profile(const fs::path& file) {
  const Json provenance = Json::parse(read_text(file), nullptr, false);
  if (!provenance.is_object() || !provenance.contains("profile") || !provenance["profile"].is_string())
    return "";
  return provenance["profile"].get<std::string>();
}

/// "quick" or "full" as the runner recorded it in the folders' provenance ("" when unknown, "mixed" when
/// the folders disagree).
std::string profile_of(const std::vector<fs::path>& folders) {
  std::string profile;
  for (const auto& folder : folders) {
    for (const auto& file : provenance_files(folder)) {
      // A provenance file being written or damaged does not decide the profile.
      const std::string found = recorded_profile(file);
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
  // The thesis' claims, then the sanity checks, as the HTML section has them.
  for (ClaimKind kind : {ClaimKind::thesis, ClaimKind::sanity}) {
    std::string rows;
    for (const auto& c : section.claims)
      if (c.kind == kind)
        rows += "| " + c.statement + " | " + to_string(c.verdict) + " | " + c.evidence +
                (c.cause.empty() ? "" : "<br>cause: " + c.cause) + " |\n";
    if (!rows.empty())
      md += std::string(kind == ClaimKind::thesis ? "## Claims\n\n" : "\n## Sanity checks\n\n") +
            "| claim | verdict | evidence |\n|---|---|---|\n" + rows;
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

ReportSummary write_report(const std::vector<fs::path>& results, const fs::path& target) {
  OutputFolder folder(target, "sextant report");
  const fs::path& out = folder.staging();
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
      config.quick = config.quick || recorded_profile(file) == "quick";
    const std::string title = config.title.empty() ? name : config.title;
    const std::vector<RunSpec> runs = expand_runs(config);
    OverviewEntry& entry = overview.emplace_back();
    entry.id = name;
    entry.title = title;
    entry.thesis = config.thesis;
    entry.profile = profile_of(folders);
    entry.real_data = config.dataset.source == DatasetSource::kFolder;
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
  write_file_atomically(out / "causes.md", "# Why claims do not hold\n\n" + causes_markdown(overview));
  write_file_atomically(out / "report.md", all_md);
  page.write(out / "index.html");
  folder.commit();
  summary.index_html = folder.target() / "index.html";
  return summary;
}

}  // namespace sextant
