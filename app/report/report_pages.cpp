#include "app/report/report_pages.h"

#include <algorithm>
#include <limits>

#include "app/plots/sweep_plot.h"
#include "app/report/report_html.h"
#include "frame/overrides_json.h"

namespace shadowlab {
namespace {

using html::escape;

const char* const kIndexTitle = "shadowlab report";

std::string indexLink() { return html::link("index.html", kIndexTitle); }

const ReportScene& sceneOf(const ReportSite& site, const ReportSource& source) {
    const auto k = size_t(&source - site.sources.data());
    return *std::ranges::find_if(site.scenes, [&](const ReportScene& s) { return std::ranges::count(s.sources, k) > 0; });
}

std::string conditionsParagraph(const ReportScene& scene) {
    return "<p class=\"conditions\">Measured under: " + escape(scene.conditions) + ".</p>\n";
}

const ReportSetting& settingOfRow(const ReportSource& source, size_t row) {
    return *std::ranges::find_if(source.settings,
                                 [&](const ReportSetting& s) { return std::ranges::count(s.rows, row) > 0; });
}

std::string settingTitle(const SweepRow& row) { return row.technique + ", " + row.settingsLabel(); }

// A render does not record its thread count.
double threadsShown(const SweepRow& row) {
    return row.threads > 0 ? double(row.threads) : std::numeric_limits<double>::quiet_NaN();
}

// ---- index.html ----

std::string scenesTable(const ReportSite& site) {
    std::string rows;
    for (const ReportScene& scene : site.scenes) {
        std::vector<std::string> techniques;
        size_t settings = 0;
        for (size_t k : scene.sources) {
            const ReportSource& source = site.sources[k];
            settings += source.settings.size();
            for (const std::string& t : source.results.techniques)
                if (std::ranges::find(techniques, t) == techniques.end()) techniques.push_back(t);
        }
        std::string names;
        for (const std::string& t : techniques) names += (names.empty() ? "" : ", ") + escape(t);
        rows += "<tr>" + html::cell(html::link(scene.page, scene.name)) + html::cell(escape(scene.conditions)) +
                html::numberCell(double(scene.sources.size()), "%.0f") + html::cell(names) +
                html::numberCell(double(settings), "%.0f") + "</tr>\n";
    }
    return html::sortableTable({"scene", "conditions", "files", "techniques", "settings"}, rows);
}

// One line per technique and scene: the settings' pages.
std::string techniquesTable(const ReportSite& site) {
    std::vector<std::string> order;
    for (const ReportSource& source : site.sources)
        for (const std::string& t : source.results.techniques)
            if (std::ranges::find(order, t) == order.end()) order.push_back(t);
    std::string rows;
    for (const std::string& technique : order) {
        for (const ReportScene& scene : site.scenes) {
            std::string links;
            for (size_t k : scene.sources) {
                const ReportSource& source = site.sources[k];
                for (const ReportSetting& setting : source.settings) {
                    const SweepRow& row = source.results.rows[setting.rows.front()];
                    if (row.technique == technique)
                        links += (links.empty() ? "" : ", ") + html::link(setting.page, row.settingsLabel());
                }
            }
            if (!links.empty())
                rows += "<tr>" + html::cell(escape(technique)) + html::cell(html::link(scene.page, scene.name)) +
                        html::cell(escape(scene.conditions)) + html::cell(links) + "</tr>\n";
        }
    }
    return html::sortableTable({"technique", "scene", "conditions", "settings"}, rows);
}

// ---- a scene's page ----

std::string describeSource(const ReportSource& source) {
    if (source.render) return "<p>One frame of <code>shadowlab render --error-map --json</code>.</p>\n";
    const SweepGrid& g = source.results.grid;
    std::string threads;
    for (int n : g.threads) threads += (threads.empty() ? "" : ", ") + std::to_string(n);
    const SweepShard& shard = source.results.shard;
    return svg::format("<p>A sweep of %zu settings", source.settings.size()) +
           (shard.count > 1 ? " (shard " + shard.name() + ")" : "") + " at " + threads +
           " thread(s); median and minimum of " + std::to_string(g.runs) + " frame(s) after " +
           std::to_string(g.warmupRuns) + " warm-up frame(s).</p>\n";
}

std::string rowsTable(const ReportSource& source) {
    std::string rows;
    for (size_t k = 0; k < source.results.rows.size(); ++k) {
        const SweepRow& r = source.results.rows[k];
        const ErrorFigures& e = r.errors;
        rows += "<tr>" + html::cell(html::link(settingOfRow(source, k).page, r.technique)) +
                html::cell(escape(r.settingsLabel())) + html::numberCell(threadsShown(r), "%.0f") +
                html::numberCell(r.medianMs, "%.4g") + html::numberCell(r.minMs, "%.4g") +
                html::numberCell(e.percentOfPixels(e.misclassified()), "%.4f") +
                html::numberCell(e.rms, "%.5f") + html::numberCell(e.maxAbs, "%.5f") +
                html::numberCell(e.percentOfPixels(e.falseShadow), "%.4f") +
                html::numberCell(e.percentOfPixels(e.falseLight), "%.4f") + "</tr>\n";
    }
    return html::sortableTable({"technique", "settings", "threads", "median ms", "min ms", "misclassified %", "RMS",
                                "max |error|", "false shadow %", "false light %"}, rows);
}

std::string sourceSection(const ReportSite& site, const ReportSource& source) {
    std::vector<std::string> links;
    for (size_t k = 0; k < source.results.rows.size(); ++k) links.push_back(settingOfRow(source, k).page);
    return "<section>\n<h2>" + escape(std::filesystem::path(source.file).filename().string()) + "</h2>\n" +
           describeSource(source) + "<div class=\"plot\">\n" + formatSweepSvg(source.results, site.plotY, links) +
           "</div>\n" + rowsTable(source) + "</section>\n";
}

// ---- a setting's page ----

// A picture at its pixel size, scaled by the zoom in whole pixels.
std::string pixelFigure(const std::string& path, const std::string& caption, const ReportSetting& setting) {
    if (path.empty()) return "";
    const std::string size =
        setting.width > 0 ? svg::format(" width=\"%d\" height=\"%d\"", setting.width, setting.height) : "";
    return "<figure><a href=\"" + escape(path) + "\"><img class=\"pixels\" src=\"" + escape(path) + "\"" + size +
           " alt=\"" + escape(caption) + "\"></a><figcaption>" + escape(caption) + "</figcaption></figure>\n";
}

// The zoom is a choice of radio buttons that CSS reads (:checked ~), so it needs no script.
std::string zoomChoice() {
    std::string inputs, labels;
    for (int zoom : {1, 2, 4, 8}) {
        inputs += svg::format("<input type=\"radio\" name=\"zoom\" id=\"zoom-%d\" class=\"zoom-%d\"%s>\n", zoom,
                              zoom, zoom == 1 ? " checked" : "");
        labels += svg::format(" <label for=\"zoom-%d\">%d&times;</label>", zoom, zoom);
    }
    return inputs + "<p class=\"zoom-choice\">Zoom, whole pixels:" + labels + "</p>\n";
}

// Hidden until report.js shows it: without a script it could not move.
std::string slider(const FrameImages& images, const SweepRow& row) {
    if (images.image.empty() || images.referenceImage.empty()) return "";
    const std::string range = "<input type=\"range\" class=\"slider-split\" min=\"0\" max=\"100\" value=\"50\">";
    return "<div class=\"slider\" hidden>\n<div class=\"slider-frame\"><img class=\"pixels slider-after\" src=\"" +
           escape(images.referenceImage) + "\" alt=\"" + escape(row.reference) +
           "\"><img class=\"pixels slider-before\" src=\"" + escape(images.image) + "\" alt=\"" +
           escape(row.technique) + "\"></div>\n<label>" + escape(row.technique) + " " + range + " " +
           escape(row.reference) + "</label>\n</div>\n";
}

std::string picturesSection(const ReportSetting& setting, const SweepRow& row) {
    const FrameImages& images = row.images;
    if (images.empty())
        return "<p>No pictures: they come from <code>shadowlab sweep --images</code>, or from <code>render -o IMAGE "
               "--error-map MAP --json FILE</code>.</p>\n";
    const std::string width = setting.width > 0 ? svg::format(" style=\"--width: %dpx\"", setting.width) : "";
    return "<section class=\"zoomable\"" + width + ">\n<h2>Pictures</h2>\n" + zoomChoice() + slider(images, row) +
           "<div class=\"figures\">\n" + pixelFigure(images.image, row.technique, setting) +
           pixelFigure(images.referenceImage, row.reference, setting) +
           pixelFigure(images.errorMap, "error map (red: false shadow, blue: false light)", setting) +
           pixelFigure(images.visibility, row.technique + " V", setting) +
           pixelFigure(images.referenceVisibility, row.reference + " V", setting) + "</div>\n</section>\n";
}

std::string figureRow(const char* name, double value, const char* format) {
    return std::string("<tr><th scope=\"row\">") + name + "</th>" + html::numberCell(value, format) + "</tr>\n";
}

// A figure the JSON predates (ErrorFigures::fullUmbraRecorded).
std::string notRecordedRow(const char* name) {
    return std::string("<tr><th scope=\"row\">") + name + "</th><td>not recorded</td></tr>\n";
}

std::string errorsTable(const SweepRow& row) {
    const ErrorFigures& e = row.errors;
    std::string rows = figureRow("pixels scored", double(e.pixels), "%.0f") + figureRow("RMS", e.rms, "%.6f") +
                       figureRow("mean |error|", e.meanAbs, "%.6f") + figureRow("max |error|", e.maxAbs, "%.6f") +
                       figureRow("misclassified %", e.percentOfPixels(e.misclassified()), "%.4f") +
                       figureRow("false shadow %", e.percentOfPixels(e.falseShadow), "%.4f") +
                       figureRow("false light %", e.percentOfPixels(e.falseLight), "%.4f") +
                       figureRow("umbra lit %", e.percentOfPixels(e.umbraLit), "%.4f") +
                       (e.fullUmbraRecorded ? figureRow("umbra lit 0.02 %", *e.fullUmbraLitPercent(), "%.4f")
                                            : notRecordedRow("umbra lit 0.02 %")) +
                       figureRow("umbra over %", e.percentOfPixels(e.umbraOver), "%.4f") +
                       figureRow("lit shadowed %", e.percentOfPixels(e.litShadowed), "%.4f");
    if (e.rmsDisplay) rows += figureRow("RMS as displayed", *e.rmsDisplay, "%.6f");
    return "<h2>Error against " + escape(row.reference) + " (on " + escape(e.channel) +
           ")</h2>\n<table class=\"figures-table\">\n<tbody>\n" + rows + "</tbody>\n</table>\n";
}

std::string timesTable(const ReportSource& source, const ReportSetting& setting) {
    std::string rows;
    for (size_t k : setting.rows) {
        const SweepRow& r = source.results.rows[k];
        rows += "<tr>" + html::numberCell(threadsShown(r), "%.0f") + html::numberCell(r.medianMs, "%.4g") +
                html::numberCell(r.minMs, "%.4g") + "</tr>\n";
    }
    return "<h2>Time of the technique</h2>\n" + html::sortableTable({"threads", "median ms", "min ms"}, rows);
}

std::string statsTable(const SweepRow& row) {
    std::string rows;
    for (const TechniqueStat& s : row.stats)
        rows += "<tr>" + html::cell(escape(s.name)) + html::numberCell(s.value, "%.6g") + "</tr>\n";
    return "<h2>Stats</h2>\n" + (rows.empty() ? "<p>The technique reports none.</p>\n"
                                              : html::sortableTable({"stat", "value"}, rows));
}

std::string debugSection(const FrameImages& images) {
    if (images.debugBuffers.empty()) return "";
    std::string figures;
    for (const std::string& path : images.debugBuffers) {
        const std::string name = std::filesystem::path(path).filename().string();
        figures += "<figure><a href=\"" + escape(path) + "\"><img class=\"debug\" src=\"" + escape(path) +
                   "\" alt=\"" + escape(name) + "\"></a><figcaption>" + escape(name) + "</figcaption></figure>\n";
    }
    return "<section>\n<h2>Debug buffers</h2>\n<div class=\"figures\">\n" + figures + "</div>\n</section>\n";
}

}  // namespace

std::string indexPage(const ReportSite& site) {
    std::string files;
    for (const ReportSource& source : site.sources) files += "<li><code>" + escape(source.file) + "</code></li>\n";
    return html::page(kIndexTitle, "", "<h2>Scenes</h2>\n" + scenesTable(site) + "<h2>Techniques</h2>\n" +
                                           techniquesTable(site) + "<h2>From</h2>\n<ul>\n" + files + "</ul>\n");
}

std::string scenePage(const ReportSite& site, const ReportScene& scene) {
    std::string body = conditionsParagraph(scene);
    for (size_t k : scene.sources) body += sourceSection(site, site.sources[k]);
    return html::page(scene.name, indexLink(), body);
}

std::string settingPage(const ReportSite& site, const ReportSource& source, const ReportSetting& setting) {
    const SweepRow& row = source.results.rows[setting.rows.front()];
    const ReportScene& scene = sceneOf(site, source);
    const std::string trail = indexLink() + " &rsaquo; " + html::link(scene.page, scene.name);
    const std::string from = "<p>Scene " + escape(scene.name) + ", from <code>" + escape(source.file) + "</code>.</p>\n" +
                             conditionsParagraph(scene);
    return html::page(settingTitle(row), trail,
                      from + picturesSection(setting, row) + errorsTable(row) + timesTable(source, setting) +
                          statsTable(row) + debugSection(row.images));
}

}  // namespace shadowlab
