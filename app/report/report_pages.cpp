#include "app/report/report_pages.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "app/plots/sweep_plot.h"
#include "app/report/report_html.h"
#include "frame/frame_images.h"
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

std::string lightName(size_t light) { return "light " + std::to_string(light); }

// The rows with, for a sweep of several lights, each light's misclassified pixels and RMS
// in columns of their own, which sort as the others do.
std::string rowsTable(const ReportSource& source) {
    const size_t lights = source.results.lightCount();
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
                html::numberCell(e.percentOfPixels(e.falseLight), "%.4f");
        for (size_t light = 0; light < lights; ++light) {
            const double nan = std::numeric_limits<double>::quiet_NaN();
            const ErrorFigures* l = light < r.lightErrors.size() ? &r.lightErrors[light] : nullptr;
            rows += html::numberCell(l ? l->percentOfPixels(l->misclassified()) : nan, "%.4f") +
                    html::numberCell(l ? l->rms : nan, "%.5f");
        }
        rows += "</tr>\n";
    }
    std::vector<std::string> columns = {"technique", "settings", "threads", "median ms", "min ms", "misclassified %",
                                        "RMS", "max |error|", "false shadow %", "false light %"};
    for (size_t light = 0; light < lights; ++light) {
        columns.push_back(lightName(light) + " misclassified %");
        columns.push_back(lightName(light) + " RMS");
    }
    // Wider than the page with several lights' columns: it scrolls, not the page.
    return "<div class=\"wide-table\">\n" + html::sortableTable(columns, rows) + "</div>\n";
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

// One figure of every column of the errors table; "not recorded" where a column's JSON
// predates it (ErrorFigures::fullUmbraRecorded).
template <class Value>
std::string figureRow(const char* name, const std::vector<const ErrorFigures*>& columns, const char* format,
                      Value value) {
    std::string row = std::string("<tr><th scope=\"row\">") + name + "</th>";
    for (const ErrorFigures* e : columns) {
        const std::optional<double> figure = value(*e);
        row += figure ? html::numberCell(*figure, format) : "<td>not recorded</td>";
    }
    return row + "</tr>\n";
}

// The figures over every light, and for a row of several lights each light's beside them.
std::string errorsTable(const SweepRow& row) {
    const ErrorFigures& e = row.errors;
    std::vector<const ErrorFigures*> columns = {&e};
    std::string header;
    if (!row.lightErrors.empty()) {
        header = "<thead><tr><td></td><th scope=\"col\">every light</th>";
        for (size_t light = 0; light < row.lightErrors.size(); ++light) {
            columns.push_back(&row.lightErrors[light]);
            header += "<th scope=\"col\">" + lightName(light) + "</th>";
        }
        header += "</tr></thead>\n";
    }
    using Figure = std::optional<double>;
    const auto percent = [](uint64_t ErrorFigures::*count) {
        return [count](const ErrorFigures& f) { return Figure(f.percentOfPixels(f.*count)); };
    };
    std::string rows =
        figureRow("pixels scored", columns, "%.0f", [](const ErrorFigures& f) { return Figure(double(f.pixels)); }) +
        figureRow("RMS", columns, "%.6f", [](const ErrorFigures& f) { return Figure(f.rms); }) +
        figureRow("mean |error|", columns, "%.6f", [](const ErrorFigures& f) { return Figure(f.meanAbs); }) +
        figureRow("max |error|", columns, "%.6f", [](const ErrorFigures& f) { return Figure(f.maxAbs); }) +
        figureRow("misclassified %", columns, "%.4f",
                  [](const ErrorFigures& f) { return Figure(f.percentOfPixels(f.misclassified())); }) +
        figureRow("false shadow %", columns, "%.4f", percent(&ErrorFigures::falseShadow)) +
        figureRow("false light %", columns, "%.4f", percent(&ErrorFigures::falseLight)) +
        figureRow("umbra lit %", columns, "%.4f", percent(&ErrorFigures::umbraLit)) +
        figureRow("umbra lit 0.02 %", columns, "%.4f", [](const ErrorFigures& f) { return f.fullUmbraLitPercent(); }) +
        figureRow("umbra over %", columns, "%.4f", percent(&ErrorFigures::umbraOver)) +
        figureRow("lit shadowed %", columns, "%.4f", percent(&ErrorFigures::litShadowed));
    if (e.rmsDisplay)
        rows += figureRow("RMS as displayed", columns, "%.6f", [](const ErrorFigures& f) { return f.rmsDisplay; });
    if (e.flipMean)
        rows += figureRow("FLIP mean", columns, "%.5f", [](const ErrorFigures& f) { return f.flipMean; });
    return "<h2>Error against " + escape(row.reference) + " (on " + escape(e.channel) +
           ")</h2>\n<table class=\"figures-table\">\n" + header + "<tbody>\n" + rows + "</tbody>\n</table>\n";
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

std::string debugFigures(const std::vector<std::string>& pictures) {
    std::string figures;
    for (const std::string& path : pictures) {
        const std::string name = std::filesystem::path(path).filename().string();
        figures += "<figure><a href=\"" + escape(path) + "\"><img class=\"debug\" src=\"" + escape(path) +
                   "\" alt=\"" + escape(name) + "\"></a><figcaption>" + escape(name) + "</figcaption></figure>\n";
    }
    return "<div class=\"figures\">\n" + figures + "</div>\n";
}

// The debug buffers, those of a frame of several lights under a heading per light
// (debugPictures() lists them light by light).
std::string debugSection(const FrameImages& images) {
    if (images.debugBuffers.empty()) return "";
    std::string body;
    std::vector<std::string> group;
    std::optional<size_t> groupLight = debugPictureLight(images.debugBuffers.front());
    const auto close = [&] {
        if (groupLight) body += "<h3>" + escape(lightName(*groupLight)) + "</h3>\n";
        body += debugFigures(group);
        group.clear();
    };
    for (const std::string& path : images.debugBuffers) {
        const std::optional<size_t> light = debugPictureLight(path);
        if (light != groupLight) close(), groupLight = light;
        group.push_back(path);
    }
    close();
    return "<section>\n<h2>Debug buffers</h2>\n" + body + "</section>\n";
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
