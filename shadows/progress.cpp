#include "shadows/progress.h"

#include <cmath>
#include <cstdio>

namespace shadowlab {
namespace {

// "m:ss", or "h:mm:ss" from an hour on.
std::string formatDuration(double seconds) {
    const long s = std::lround(seconds);
    char text[32];
    if (s < 3600) std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    else std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    return text;
}

// "what 12/40 (30%), 0:09 elapsed, ~0:21 left"; the estimate assumes the remaining units
// take as long on average as the done ones did.
std::string formatLine(const std::string& what, uint64_t done, uint64_t total, double elapsed) {
    std::string line = what + " " + std::to_string(done) + "/" + std::to_string(total);
    if (total > 0) line += " (" + std::to_string(100 * done / total) + "%)";
    line += ", " + formatDuration(elapsed) + " elapsed";
    if (done > 0 && done < total) line += ", ~" + formatDuration(elapsed * double(total - done) / double(done)) + " left";
    return line;
}

}  // namespace

Progress::Progress(std::ostream& out, std::function<Clock::time_point()> now) : out_(out), now_(std::move(now)) {}

void Progress::begin(std::string what, uint64_t total) {
    const std::lock_guard lock(mutex_);
    what_ = std::move(what);
    total_ = total;
    done_ = 0;
    start_ = now_();
    line_.clear();
}

void Progress::advance(uint64_t units) {
    done_.fetch_add(units, std::memory_order_relaxed);
    // A thread that finds another drawing skips: that one shows the count as good as this one.
    const std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) return;
    const Clock::time_point now = now_();
    if (now - start_ < kDelay || (!line_.empty() && now - lastDraw_ < kInterval)) return;
    draw(now);
}

void Progress::end() {
    const std::lock_guard lock(mutex_);
    if (line_.empty()) return;
    draw(now_());
    out_ << '\n' << std::flush;
    line_.clear();
}

void Progress::draw(Clock::time_point now) {
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::string line = formatLine(what_, done_.load(std::memory_order_relaxed), total_, elapsed);
    lastDraw_ = now;
    if (line == line_) return;
    out_ << '\r' << line << std::string(line_.size() > line.size() ? line_.size() - line.size() : 0, ' ') << std::flush;
    line_ = std::move(line);
}

ProgressStage::ProgressStage(Progress* progress, std::string what, uint64_t total) : progress_(progress) {
    if (progress_) progress_->begin(std::move(what), total);
}

ProgressStage::~ProgressStage() {
    if (progress_) progress_->end();
}

void ProgressStage::advance(uint64_t units) const {
    if (progress_) progress_->advance(units);
}

}  // namespace shadowlab
