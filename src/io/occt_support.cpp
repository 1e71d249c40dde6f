#include "io/occt_support.h"

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <TCollection_AsciiString.hxx>

namespace vox::io::occt {
namespace {

std::mutex g_reader_mutex;
std::vector<std::string>* g_failures = nullptr;  // guarded by g_reader_mutex; set while a ReaderLock is held
std::mutex g_failures_mutex;                     // OCCT may send from its worker threads

constexpr size_t kMaxFailures = 4;
constexpr size_t kMaxFailureChars = 200;

// Printable ASCII only, spaces collapsed, trimmed: OCCT's messages carry colour escapes and newlines.
std::string cleaned(const char* text) {
  std::string out;
  bool space = false;
  for (const char* p = text; *p != '\0' && out.size() < kMaxFailureChars; ++p) {
    const unsigned char c = static_cast<unsigned char>(*p);
    if (c == 0x1b) {  // ANSI colour: ESC [ ... m
      while (p[1] != '\0' && p[1] != 'm') ++p;
      if (p[1] == 'm') ++p;
      continue;
    }
    if (c <= ' ' || c > '~' || c == '*') {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += char(c);
  }
  return out;
}

class Collector : public Message_Printer {
 protected:
  void send(const TCollection_AsciiString& text, const Message_Gravity gravity) const override {
    if (gravity < Message_Fail) return;
    std::lock_guard<std::mutex> lock(g_failures_mutex);
    if (g_failures == nullptr || g_failures->size() >= kMaxFailures) return;
    std::string s = cleaned(text.ToCString());
    if (!s.empty()) g_failures->push_back(std::move(s));
  }
};

}  // namespace

void silenceMessages() {
  static std::once_flag once;
  std::call_once(once, [] {
    const Handle(Message_Messenger)& messenger = Message::DefaultMessenger();
    messenger->ChangePrinters().Clear();
    messenger->AddPrinter(new Collector());
  });
}

ReaderLock::ReaderLock() : lock_(g_reader_mutex) {
  silenceMessages();
  std::lock_guard<std::mutex> guard(g_failures_mutex);
  g_failures = new std::vector<std::string>();
}

ReaderLock::~ReaderLock() {
  std::lock_guard<std::mutex> guard(g_failures_mutex);
  delete g_failures;
  g_failures = nullptr;
}

std::vector<std::string> ReaderLock::failures() const {
  std::lock_guard<std::mutex> guard(g_failures_mutex);
  return g_failures ? *g_failures : std::vector<std::string>();
}

void ProgressBridge::Show(const Message_ProgressScope&, const Standard_Boolean) {
  if (!progress_ || cancelled_.load(std::memory_order_relaxed)) return;
  const double position = GetPosition();
  if (!progress_(from_ + (to_ - from_) * position)) cancelled_.store(true, std::memory_order_relaxed);
}

std::string failureText(const Standard_Failure& failure) {
  std::string s = cleaned(failure.GetMessageString());
  const std::string type = failure.DynamicType()->Name();
  return s.empty() ? type : type + ": " + s;
}

}  // namespace vox::io::occt
