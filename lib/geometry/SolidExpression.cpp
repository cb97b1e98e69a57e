#include "geometry/SolidExpression.hpp"

#include "core/Error.hpp"

#include <cctype>

namespace mfwave {
namespace {

bool isNameCharacter(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Recursive descent over: expression := term { ('+' | '-') term }, term := factor { '&' factor },
// factor := name | '(' expression ')'.
template <int D>
class ExpressionParser {
 public:
  ExpressionParser(const std::string& text, const std::function<SolidPtr<D>(const std::string&)>& lookup,
                   const std::vector<std::string>& known, const std::string& key)
      : text_(text), lookup_(lookup), known_(known), key_(key) {}

  SolidPtr<D> parse() {
    skipSpace();
    if (at_ == text_.size()) fail("is empty: name a shape (the scene's box is 'box')");
    SolidPtr<D> solid = expression();
    skipSpace();
    if (at_ != text_.size()) fail("unexpected '" + std::string(1, text_[at_]) + "'");
    return solid;
  }

 private:
  SolidPtr<D> expression() {
    SolidPtr<D> left = term();
    for (;;) {
      skipSpace();
      if (at_ < text_.size() && (text_[at_] == '+' || text_[at_] == '-')) {
        const char op = text_[at_++];
        SolidPtr<D> right = term();
        left = op == '+' ? unite<D>(left, right) : subtract<D>(left, right);
      } else {
        return left;
      }
    }
  }
  SolidPtr<D> term() {
    SolidPtr<D> left = factor();
    for (;;) {
      skipSpace();
      if (at_ < text_.size() && text_[at_] == '&') {
        ++at_;
        left = intersect<D>(left, factor());
      } else {
        return left;
      }
    }
  }
  SolidPtr<D> factor() {
    skipSpace();
    if (at_ == text_.size()) fail("ends where a shape's name or '(' is expected");
    if (text_[at_] == '(') {
      ++at_;
      SolidPtr<D> inner = expression();
      skipSpace();
      if (at_ == text_.size() || text_[at_] != ')') fail("misses a ')'");
      ++at_;
      return inner;
    }
    const std::size_t start = at_;
    while (at_ < text_.size() && isNameCharacter(text_[at_])) ++at_;
    if (at_ == start) fail("expects a shape's name or '(' but finds '" + std::string(1, text_[at_]) + "'");
    const std::string name = text_.substr(start, at_ - start);
    SolidPtr<D> solid = lookup_(name);
    if (!solid) {
      std::string names;
      for (const std::string& n : known_) names += (names.empty() ? "" : ", ") + n;
      at_ = start;
      fail("names no shape '" + name + "' (known: " + names + ")");
    }
    return solid;
  }
  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])) != 0) ++at_;
  }
  [[noreturn]] void fail(const std::string& problem) const {
    throw InputError(key_, "'" + text_ + "' " + problem + " (at character " + std::to_string(at_ + 1) + ")");
  }

  const std::string& text_;
  const std::function<SolidPtr<D>(const std::string&)>& lookup_;
  const std::vector<std::string>& known_;
  const std::string& key_;
  std::size_t at_ = 0;
};

}  // namespace

template <int D>
SolidPtr<D> parseSolidExpression(const std::string& text, const std::function<SolidPtr<D>(const std::string&)>& lookup,
                                 const std::vector<std::string>& known, const std::string& key) {
  return ExpressionParser<D>(text, lookup, known, key).parse();
}

std::vector<std::string> solidExpressionNames(const std::string& text) {
  std::vector<std::string> names;
  for (std::size_t i = 0; i < text.size();) {
    if (!isNameCharacter(text[i])) {
      ++i;
      continue;
    }
    const std::size_t start = i;
    while (i < text.size() && isNameCharacter(text[i])) ++i;
    const std::string name = text.substr(start, i - start);
    bool seen = false;
    for (const std::string& n : names) seen = seen || n == name;
    if (!seen) names.push_back(name);
  }
  return names;
}

template SolidPtr<2> parseSolidExpression<2>(const std::string&, const std::function<SolidPtr<2>(const std::string&)>&,
                                             const std::vector<std::string>&, const std::string&);
template SolidPtr<3> parseSolidExpression<3>(const std::string&, const std::function<SolidPtr<3>(const std::string&)>&,
                                             const std::vector<std::string>&, const std::string&);

}  // namespace mfwave
