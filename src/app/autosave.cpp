#include "app/autosave.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <system_error>
#include <thread>

#include "app/document.h"
#include "app/messages.h"
#include "app/project.h"
#include "vox/core/text.h"
#include "vox/io/file_util.h"
#include "vox/io/project_file.h"

namespace vox::app {
namespace {

constexpr const char* kPrefix = "autosave-";
constexpr double kDefaultIntervalS = 30.0;

std::filesystem::path autosaveDirectory(bool scripted) {
  if (const char* dir = std::getenv("VOXMOD_AUTOSAVE_DIR"); dir && *dir) return dir;
  if (scripted) return {};  // a test or a screenshot run leaves the user's autosaves alone
  if (const char* state = std::getenv("XDG_STATE_HOME"); state && *state) {
    return std::filesystem::path(state) / "voxmod" / "autosave";
  }
  if (const char* home = std::getenv("HOME"); home && *home) {
    return std::filesystem::path(home) / ".local" / "state" / "voxmod" / "autosave";
  }
  return {};
}

// When process `pid` started (clock ticks since boot, /proc/PID/stat field 22); 0 when it does not run (or is a
// zombie) or /proc cannot say.
uint64_t processStart(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return 0;
  const size_t close = stat.rfind(')');  // the command name may hold spaces and parentheses
  if (close == std::string::npos) return 0;
  std::istringstream fields(stat.substr(close + 1));
  std::string state;
  fields >> state;
  if (state == "Z" || state == "X") return 0;
  std::string skip;
  for (int i = 0; i < 18; ++i) fields >> skip;  // fields 4..21
  uint64_t start = 0;
  fields >> start;
  return start;
}

std::string hostName() {
  char buf[256] = {};
  if (::gethostname(buf, sizeof buf - 1) != 0) return "host";
  std::string h(buf);
  std::replace_if(
      h.begin(), h.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)) && c != '.'; }, '_');
  return h.empty() ? "host" : h;
}

// This window's autosave: autosave-HOST-PID-START.vxp (the process's start time tells it from an earlier process
// that had the same PID).
std::string ownName() {
  return std::string(kPrefix) + hostName() + "-" + std::to_string(::getpid()) + "-" +
         std::to_string(processStart(long(::getpid()))) + ".vxp";
}

// An autosave of this host whose window is gone: the process of its PID does not run, or is another process (it
// started at another time). Autosaves of other hosts (a shared home) are never taken: their windows may run.
bool orphaned(const std::filesystem::path& file, const std::string& host) {
  const std::string stem = file.stem().string();  // autosave-HOST-PID-START
  const size_t b = stem.rfind('-'), a = b == std::string::npos ? b : stem.rfind('-', b - 1);
  if (a == std::string::npos || a < std::string_view(kPrefix).size()) return false;
  if (stem.substr(std::string_view(kPrefix).size(), a - std::string_view(kPrefix).size()) != host) return false;
  long pid = 0;
  uint64_t start = 0;
  if (!parseNumber(std::string_view(stem).substr(a + 1, b - a - 1), pid) ||
      !parseNumber(std::string_view(stem).substr(b + 1), start) || pid <= 0) {
    return false;
  }
  const uint64_t now = processStart(pid);
  if (now == 0) return ::kill(pid_t(pid), 0) != 0 && errno == ESRCH;  // gone (or no /proc to ask: ask the kernel)
  return now != start;
}

std::string localTime(std::filesystem::file_time_type t) {
  const std::time_t tt = std::chrono::system_clock::to_time_t(std::chrono::file_clock::to_sys(t));
  std::tm tm{};
  localtime_r(&tt, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", &tm);
  return buf;
}

// The autosaves in `dir` of windows that are gone, newest first. The temporary files of writes they did not finish
// are removed.
std::vector<OrphanAutosave> findOrphans(const std::filesystem::path& dir) {
  std::vector<std::pair<std::filesystem::file_time_type, OrphanAutosave>> found;
  const std::string host = hostName();
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::filesystem::path& p = e.path();
    const std::string name = p.filename().string();
    if (name.rfind(std::string(".") + kPrefix, 0) == 0) {  // ".autosave-...vxp.tmp...": an unfinished write
      const std::filesystem::path target = p.parent_path() / name.substr(1, name.find(".vxp") + 3);
      if (orphaned(target, host)) std::filesystem::remove(p, ec);
      continue;
    }
    if (p.extension() != ".vxp" || name.rfind(kPrefix, 0) != 0 || !orphaned(p, host)) continue;
    const auto t = std::filesystem::last_write_time(p, ec);
    if (ec) continue;
    OrphanAutosave o;
    o.path = p;
    o.when = localTime(t);
    const std::string source = io::projectSource(p);  // the manifest alone: no grid is decoded here
    o.document = source.empty() ? std::string("an unnamed model") : std::filesystem::path(source).filename().string();
    found.emplace_back(t, std::move(o));
  }
  std::sort(found.begin(), found.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<OrphanAutosave> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

AutosaveState::Key currentKey(const AppState& state) {
  return {state.doc.model->version, state.doc.model->parts.get(), state.doc.undo_stack.size(), int(state.panel),
          int(state.section.axis),  state.section.index,          state.parts_ui.selected};
}

void removeFile(AutosaveState& a) {
  if (!a.file_written) return;
  std::error_code ec;
  std::filesystem::remove(a.file, ec);
  a.file_written = false;
  a.written = {};
}

void takeWrite(AppState& state) {
  AutosaveState& a = state.autosave;
  auto r = a.job.take();
  if (!r) return;
  if (r->ok()) {
    a.written = r->value();
    a.file_written = true;
    a.last_error.clear();
  } else if (a.last_error != r->error().message) {  // said once, in the status bar: autosave never interrupts
    a.last_error = r->error().message;
    state.status_message = "Autosave failed: " + a.last_error;
    state.status_since = nowSeconds();
  }
}

// Waits for a write under way (it would land over what comes next).
void waitForWrite(AutosaveState& a) {
  while (a.job.active()) {
    if (!a.job.take()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

void initAutosave(AppState& state, bool scripted) {
  AutosaveState& a = state.autosave;
  a.dir = autosaveDirectory(scripted);
  if (a.dir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(a.dir, ec);
  a.file = a.dir / ownName();
  a.interval_s = kDefaultIntervalS;
  if (const char* s = std::getenv("VOXMOD_AUTOSAVE_SECONDS"); s && *s) {
    double v = 0.0;
    if (parseNumber(std::string_view(s), v) && v >= 0.0) a.interval_s = v;
  }
  a.last_write = nowSeconds();
  a.orphans = findOrphans(a.dir);
}

void updateAutosave(AppState& state) {
  AutosaveState& a = state.autosave;
  if (a.dir.empty()) return;
  takeWrite(state);
  if (a.job.active()) return;
  if (!state.doc.model || !hasUnsavedChanges(state)) {
    removeFile(a);  // nothing would be lost: nothing to recover
    return;
  }
  const AutosaveState::Key key = currentKey(state);
  if (a.file_written && key == a.written) return;
  if (nowSeconds() - a.last_write < a.interval_s) return;
  a.last_write = nowSeconds();
  a.job.start("Autosaving",
              [project = projectOf(state), path = a.file, key](const ProgressFn&) -> Result<AutosaveState::Key> {
                if (Status s = io::saveProject(project, path); !s) return s.error();
                return key;
              });
}

bool autosaveBusy(const AppState& state) { return state.autosave.job.active(); }

void finishAutosave(AppState& state) {
  AutosaveState& a = state.autosave;
  if (a.dir.empty()) return;
  waitForWrite(a);
  a.file_written = true;  // whatever the last write did, the file goes
  removeFile(a);
}

void recoverAutosave(AppState& state) {
  AutosaveState& a = state.autosave;
  if (a.orphans.empty()) return;
  const OrphanAutosave o = a.orphans.front();
  a.orphans.erase(a.orphans.begin());
  startRecover(state, o.path);
}

void adoptRecovered(AppState& state, const std::filesystem::path& orphan) {
  AutosaveState& a = state.autosave;
  std::error_code ec;
  if (a.dir.empty() || !state.doc.model) return;
  waitForWrite(a);                              // the previous document's write must not land over the recovered one
  std::filesystem::rename(orphan, a.file, ec);  // this window's now: a crash before its next write loses nothing
  if (ec) return;
  a.file_written = true;
  a.written = currentKey(state);
}

void discardAutosave(AppState& state) {
  AutosaveState& a = state.autosave;
  if (a.orphans.empty()) return;
  std::error_code ec;
  std::filesystem::remove(a.orphans.front().path, ec);
  a.orphans.erase(a.orphans.begin());
}

}  // namespace vox::app
