#include "material/located_json.h"

#include <algorithm>
#include <iterator>
#include <optional>

#include "base/echoed_text.h"

namespace matc {
namespace {

using nlohmann::json;

// An input iterator over the text that records the furthest position the lexer has reached.
class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* position, const char* begin, std::size_t* furthest)
      : position_(position), begin_(begin), furthest_(furthest) {}
  reference operator*() const { return *position_; }
  CountingIterator& operator++() {
    ++position_;
    *furthest_ = std::max(*furthest_, static_cast<std::size_t>(position_ - begin_));
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return position_ == other.position_; }

 private:
  const char* position_;
  const char* begin_;
  std::size_t* furthest_;
};

std::string escape_pointer_token(const std::string& token) {
  std::string out;
  for (const char c : token) {
    if (c == '~') {
      out += "~0";
    } else if (c == '/') {
      out += "~1";
    } else {
      out += c;
    }
  }
  return out;
}

class LocatingHandler {
 public:
  LocatingHandler(std::string_view text, const std::size_t* consumed)
      : text_(text), consumed_(consumed) {}

  bool null() { return add_value(nullptr); }
  bool boolean(bool value) { return add_value(value); }
  bool number_integer(json::number_integer_t value) { return add_value(value); }
  bool number_unsigned(json::number_unsigned_t value) { return add_value(value); }
  bool number_float(json::number_float_t value, const json::string_t& /*text*/) {
    return add_value(value);
  }
  bool string(json::string_t& value) { return add_value(std::move(value)); }
  bool binary(json::binary_t& /*value*/) { return false; }  // never produced by text JSON

  bool start_object(std::size_t /*size*/) { return open(json::object()); }
  bool start_array(std::size_t /*size*/) { return open(json::array()); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }

  bool key(json::string_t& key) {
    const std::size_t offset = token_start();
    Frame& frame = frames_.back();
    frame.key = key;
    const std::string pointer = frame.pointer + "/" + escape_pointer_token(key);
    if (frame.container->contains(key)) {
      result_.duplicates.push_back({pointer, offset, result_.key_offsets.at(pointer)});
    } else {
      result_.key_offsets[pointer] = offset;
    }
    return true;
  }

  bool parse_error(std::size_t position, const std::string& /*last_token*/,
                   const json::exception& error) {
    // Drop nlohmann's "[json.exception.parse_error.101] " and "parse error at line 1, column 2: ":
    // the diagnostic carries its own position.
    std::string_view message = error.what();
    if (const auto bracket = message.find("] ");
        !message.empty() && message.front() == '[' && bracket != std::string_view::npos) {
      message.remove_prefix(bracket + 2);
    }
    if (message.starts_with("parse error")) {
      if (const auto colon = message.find(": "); colon != std::string_view::npos) {
        message.remove_prefix(colon + 2);
      }
    }
    error_ = JsonSyntaxError{position > 0 ? position - 1 : 0, std::string(message)};
    return false;
  }

  std::variant<LocatedJson, JsonSyntaxError> finish() {
    if (error_) return *error_;
    return std::move(result_);
  }

 private:
  struct Frame {
    json* container;
    std::string pointer;
    std::string key;  // the pending member name, for objects
  };

  // The first byte of the current token: skip what may separate it from the previous event.
  std::size_t token_start() {
    std::size_t at = last_end_;
    while (at < text_.size() && (text_[at] == ' ' || text_[at] == '\t' || text_[at] == '\n' ||
                                 text_[at] == '\r' || text_[at] == ',' || text_[at] == ':')) {
      ++at;
    }
    last_end_ = *consumed_;
    return at;
  }

  // Inserts `value` where the parser is and returns it with its JSON pointer.
  std::pair<json*, std::string> insert(json&& value) {
    const std::size_t offset = token_start();
    if (frames_.empty()) {
      result_.value = std::move(value);
      result_.value_offsets[""] = offset;
      return {&result_.value, ""};
    }
    Frame& frame = frames_.back();
    json* slot = nullptr;
    std::string pointer;
    if (frame.container->is_array()) {
      pointer = frame.pointer + "/" + std::to_string(frame.container->size());
      frame.container->push_back(std::move(value));
      slot = &frame.container->back();
    } else {
      pointer = frame.pointer + "/" + escape_pointer_token(frame.key);
      slot = &((*frame.container)[frame.key] = std::move(value));
    }
    result_.value_offsets[pointer] = offset;
    return {slot, pointer};
  }

  bool add_value(json&& value) {
    insert(std::move(value));
    return true;
  }

  bool open(json&& container) {
    if (frames_.size() >= kMaxJsonDepth) {
      error_ = JsonSyntaxError{token_start(), "nesting deeper than 64 levels"};
      return false;
    }
    auto [slot, pointer] = insert(std::move(container));
    frames_.push_back({slot, std::move(pointer), {}});
    return true;
  }

  bool close() {
    last_end_ = *consumed_;
    result_.container_ends[frames_.back().pointer] = *consumed_;
    frames_.pop_back();
    return true;
  }

  std::string_view text_;
  const std::size_t* consumed_;
  std::size_t last_end_ = 0;
  std::vector<Frame> frames_;
  LocatedJson result_;
  std::optional<JsonSyntaxError> error_;
};

}  // namespace

std::size_t LocatedJson::value_offset(const std::string& pointer) const {
  const auto found = value_offsets.find(pointer);
  return found == value_offsets.end() ? 0 : found->second;
}

std::size_t LocatedJson::key_or_value_offset(const std::string& pointer) const {
  const auto found = key_offsets.find(pointer);
  return found == key_offsets.end() ? value_offset(pointer) : found->second;
}

std::variant<LocatedJson, JsonSyntaxError> parse_located_json(std::string_view text) {
  // nlohmann's lexer reads a NUL byte as the end of the input: text after one would be ignored.
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    return JsonSyntaxError{nul, "a NUL byte (JSON text holds none; a string writes it \\u0000)"};
  std::size_t consumed = 0;
  LocatingHandler handler(text, &consumed);
  const char* begin = text.data();
  json::sax_parse(CountingIterator(begin, begin, &consumed),
                  CountingIterator(begin + text.size(), begin, &consumed), &handler,
                  json::input_format_t::json, /*strict=*/true, /*ignore_comments=*/false);
  return handler.finish();
}

std::string field_path(std::string_view pointer) {
  std::string out;
  std::size_t start = 0;
  while (start < pointer.size()) {  // each token is preceded by '/'
    std::size_t end = pointer.find('/', start + 1);
    if (end == std::string_view::npos) end = pointer.size();
    const std::string_view escaped = pointer.substr(start + 1, end - start - 1);
    std::string token;  // RFC 6901: "~1" is '/', "~0" is '~'
    for (std::size_t i = 0; i < escaped.size(); ++i) {
      if (escaped[i] == '~' && i + 1 < escaped.size()) {
        token += escaped[++i] == '1' ? '/' : '~';
      } else {
        token += escaped[i];
      }
    }
    const bool index = !token.empty() && std::all_of(token.begin(), token.end(),
                                                     [](char c) { return c >= '0' && c <= '9'; });
    // A key is input text: escaped and cut, as every echoed piece of input is.
    if (index) {
      out.append("[").append(token).append("]");
    } else {
      if (!out.empty()) out.push_back('.');
      out.append(echoed(token));
    }
    start = end;
  }
  return out;
}

}  // namespace matc
