#include "renderer/scene/pbrt/pbrt_parser.h"

#include "renderer/scene/text_file.h"
#include "sampling/core/errors.h"

#include <charconv>
#include <cmath>
#include <map>
#include <memory>

namespace fs = std::filesystem;

namespace pdrt {
namespace {

// What follows a directive's name (pbrt-v4's file-format documentation).
enum class Shape {
  Nothing,            // AttributeBegin, WorldBegin, ...
  Numbers,            // a fixed count of numbers: Translate 3, Rotate 4, LookAt 9, TransformTimes 2
  Matrix,             // 16 numbers, bracketed or bare: Transform, ConcatTransform
  OneString,          // CoordinateSystem "name", Include "file", ...
  Word,               // ActiveTransform StartTime|EndTime|All
  StringParams,       // Shape "sphere" params, Camera "perspective" params, ...
  ThreeStringParams,  // Texture "name" "spectrum" "imagemap" params
  Strings12,          // MediumInterface "inside" ["outside"]
  Params,             // Option "bool name" value
};

struct Syntax {
  PbrtDirectiveKind kind;
  Shape shape;
  int count = 0;  // Numbers: how many
};

const std::map<std::string, Syntax, std::less<>>& syntax() {
  using K = PbrtDirectiveKind;
  static const std::map<std::string, Syntax, std::less<>> table = {
      {"AttributeBegin", {K::AttributeBegin, Shape::Nothing}},
      {"AttributeEnd", {K::AttributeEnd, Shape::Nothing}},
      {"TransformBegin", {K::TransformBegin, Shape::Nothing}},
      {"TransformEnd", {K::TransformEnd, Shape::Nothing}},
      {"WorldBegin", {K::WorldBegin, Shape::Nothing}},
      {"WorldEnd", {K::WorldEnd, Shape::Nothing}},
      {"ReverseOrientation", {K::ReverseOrientation, Shape::Nothing}},
      {"Identity", {K::Identity, Shape::Nothing}},
      {"ObjectEnd", {K::ObjectEnd, Shape::Nothing}},
      {"Translate", {K::Translate, Shape::Numbers, 3}},
      {"Scale", {K::Scale, Shape::Numbers, 3}},
      {"Rotate", {K::Rotate, Shape::Numbers, 4}},
      {"LookAt", {K::LookAt, Shape::Numbers, 9}},
      {"TransformTimes", {K::TransformTimes, Shape::Numbers, 2}},
      {"Transform", {K::Transform, Shape::Matrix}},
      {"ConcatTransform", {K::ConcatTransform, Shape::Matrix}},
      {"CoordinateSystem", {K::CoordinateSystem, Shape::OneString}},
      {"CoordSysTransform", {K::CoordSysTransform, Shape::OneString}},
      {"ColorSpace", {K::ColorSpace, Shape::OneString}},
      {"NamedMaterial", {K::NamedMaterial, Shape::OneString}},
      {"ObjectBegin", {K::ObjectBegin, Shape::OneString}},
      {"ObjectInstance", {K::ObjectInstance, Shape::OneString}},
      {"Include", {K::Include, Shape::OneString}},
      {"Import", {K::Import, Shape::OneString}},
      {"ActiveTransform", {K::ActiveTransform, Shape::Word}},
      {"Camera", {K::Camera, Shape::StringParams}},
      {"Film", {K::Film, Shape::StringParams}},
      {"Sampler", {K::Sampler, Shape::StringParams}},
      {"PixelFilter", {K::PixelFilter, Shape::StringParams}},
      {"Integrator", {K::Integrator, Shape::StringParams}},
      {"Accelerator", {K::Accelerator, Shape::StringParams}},
      {"Material", {K::Material, Shape::StringParams}},
      {"MakeNamedMaterial", {K::MakeNamedMaterial, Shape::StringParams}},
      {"Shape", {K::Shape, Shape::StringParams}},
      {"LightSource", {K::LightSource, Shape::StringParams}},
      {"AreaLightSource", {K::AreaLightSource, Shape::StringParams}},
      {"MakeNamedMedium", {K::MakeNamedMedium, Shape::StringParams}},
      {"Attribute", {K::Attribute, Shape::StringParams}},
      {"Texture", {K::Texture, Shape::ThreeStringParams}},
      {"MediumInterface", {K::MediumInterface, Shape::Strings12}},
      {"Option", {K::Option, Shape::Params}},
  };
  return table;
}

constexpr int kMaxIncludeDepth = 64;

class Parser {
 public:
  explicit Parser(std::vector<PbrtDirective>* out) : out_(out) {}

  void parse_file(const fs::path& file, const std::string& shown, const PbrtLocation* included_at) {
    std::error_code ec;
    fs::path canon = fs::weakly_canonical(file, ec);
    if (ec) canon = file;
    for (const fs::path& open : stack_)
      if (open == canon)
        throw InputError(included_at->str() + ": \"" + shown + "\" includes itself (an Include cycle)");
    if (int(stack_.size()) >= kMaxIncludeDepth)
      throw InputError(included_at->str() + ": Include is nested more than " + std::to_string(kMaxIncludeDepth) +
                       " deep");
    std::string reason;
    std::optional<std::string> text = read_text_file(file, reason);
    if (!text) {
      if (included_at) throw InputError(included_at->str() + ": cannot open \"" + shown + "\": " + reason);
      throw InputError("cannot open " + shown + ": " + reason);
    }
    stack_.push_back(canon);
    parse_text(*text, shown, file.parent_path());
    stack_.pop_back();
  }

  void parse_text(std::string_view text, const std::string& shown, const fs::path& dir) {
    auto name = std::make_shared<const std::string>(shown);
    PbrtTokenizer tok(text, name);
    Lookahead in{&tok, std::nullopt};
    for (;;) {
      PbrtToken t = in.take();
      if (t.kind == PbrtToken::Kind::End) return;
      if (t.kind != PbrtToken::Kind::Word) throw InputError(t.at.str() + ": expected a directive, got " + describe(t));
      auto it = syntax().find(t.text);
      if (it == syntax().end()) throw InputError(t.at.str() + ": unknown directive \"" + t.text + "\"");
      PbrtDirective d;
      d.name = t.text;
      d.kind = it->second.kind;
      d.at = t.at;
      directive(in, it->second, d);
      if (d.kind == PbrtDirectiveKind::Include || d.kind == PbrtDirectiveKind::Import) {
        fs::path target = fs::path(d.strings[0]);
        if (target.is_relative()) target = dir / target;
        std::string shown_target = (fs::path(shown).parent_path() / d.strings[0]).string();
        if (fs::path(d.strings[0]).is_absolute()) shown_target = d.strings[0];
        parse_file(target, shown_target, &d.at);
        continue;
      }
      out_->push_back(std::move(d));
    }
  }

 private:
  struct Lookahead {
    PbrtTokenizer* tok;
    std::optional<PbrtToken> peeked;
    const PbrtToken& peek() {
      if (!peeked) peeked = tok->next();
      return *peeked;
    }
    PbrtToken take() {
      if (peeked) {
        PbrtToken t = std::move(*peeked);
        peeked.reset();
        return t;
      }
      return tok->next();
    }
  };

  static std::string describe(const PbrtToken& t) {
    switch (t.kind) {
      case PbrtToken::Kind::Word:
        return "\"" + t.text + "\"";
      case PbrtToken::Kind::String:
        return "the string \"" + t.text + "\"";
      case PbrtToken::Kind::Open:
        return "'['";
      case PbrtToken::Kind::Close:
        return "']'";
      default:
        return "the end of the file";
    }
  }

  static double number(const PbrtToken& t, const std::string& what) {
    if (t.kind != PbrtToken::Kind::Word)
      throw InputError(t.at.str() + ": " + what + " must be a number, got " + describe(t));
    const char* b = t.text.data();
    const char* e = b + t.text.size();
    if (b != e && *b == '+') ++b;
    double v = 0;
    auto [ptr, ec] = std::from_chars(b, e, v);
    if (ec == std::errc::result_out_of_range)
      throw InputError(t.at.str() + ": " + what + " " + t.text + " is out of range");
    if (ec != std::errc() || ptr != e || !std::isfinite(v))
      throw InputError(t.at.str() + ": " + what + " must be a number, got \"" + t.text + "\"");
    return v;
  }

  static std::string string_arg(Lookahead& in, const PbrtDirective& d) {
    PbrtToken t = in.take();
    if (t.kind != PbrtToken::Kind::String)
      throw InputError(t.at.str() + ": " + d.name + " needs a quoted string, got " + describe(t));
    return t.text;
  }

  void directive(Lookahead& in, const Syntax& s, PbrtDirective& d) {
    switch (s.shape) {
      case Shape::Nothing:
        return;
      case Shape::Numbers:
        for (int i = 0; i < s.count; ++i)
          d.numbers.push_back(number(in.take(), d.name + " argument " + std::to_string(i + 1)));
        return;
      case Shape::Matrix: {
        bool bracket = in.peek().kind == PbrtToken::Kind::Open;
        if (bracket) in.take();
        for (int i = 0; i < 16; ++i) {
          if (bracket && in.peek().kind == PbrtToken::Kind::Close)
            throw InputError(in.peek().at.str() + ": " + d.name + " needs 16 numbers, got " + std::to_string(i));
          d.numbers.push_back(number(in.take(), d.name + " element " + std::to_string(i + 1)));
        }
        if (bracket) {
          PbrtToken t = in.take();
          if (t.kind != PbrtToken::Kind::Close)
            throw InputError(t.at.str() + ": " + d.name + " needs exactly 16 numbers and a ']', got " + describe(t));
        }
        return;
      }
      case Shape::OneString:
        d.strings.push_back(string_arg(in, d));
        return;
      case Shape::Word: {
        PbrtToken t = in.take();
        if (t.kind != PbrtToken::Kind::Word || (t.text != "StartTime" && t.text != "EndTime" && t.text != "All"))
          throw InputError(t.at.str() + ": " + d.name + " takes StartTime, EndTime or All, got " + describe(t));
        d.strings.push_back(t.text);
        return;
      }
      case Shape::StringParams:
        d.strings.push_back(string_arg(in, d));
        params(in, d);
        return;
      case Shape::ThreeStringParams:
        for (int i = 0; i < 3; ++i) d.strings.push_back(string_arg(in, d));
        params(in, d);
        return;
      case Shape::Strings12:
        d.strings.push_back(string_arg(in, d));
        if (in.peek().kind == PbrtToken::Kind::String) d.strings.push_back(in.take().text);
        return;
      case Shape::Params:
        params(in, d);
        if (d.params.list.empty()) throw InputError(d.at.str() + ": Option needs a \"type name\" value");
        return;
    }
  }

  // `"type name" value` pairs until the next token is not a string.
  void params(Lookahead& in, PbrtDirective& d) {
    while (in.peek().kind == PbrtToken::Kind::String) {
      PbrtToken decl = in.take();
      PbrtParam p;
      p.at = decl.at;
      size_t a = decl.text.find_first_not_of(" \t");
      size_t b = a == std::string::npos ? a : decl.text.find_first_of(" \t", a);
      size_t c = b == std::string::npos ? b : decl.text.find_first_not_of(" \t", b);
      size_t e = c == std::string::npos ? c : decl.text.find_first_of(" \t", c);
      if (a == std::string::npos || c == std::string::npos ||
          (e != std::string::npos && decl.text.find_first_not_of(" \t", e) != std::string::npos))
        throw InputError(decl.at.str() + ": a parameter is declared as \"type name\", got \"" + decl.text + "\"");
      p.type = decl.text.substr(a, b - a);
      p.name = decl.text.substr(c, e == std::string::npos ? std::string::npos : e - c);
      const std::string type = pbrt_canonical_type(p.type);
      if (type.empty())
        throw InputError(decl.at.str() + ": unknown parameter type \"" + p.type + "\" (of \"" + p.name + "\")");
      for (const PbrtParam& q : d.params.list)
        if (q.name == p.name)
          throw InputError(decl.at.str() + ": parameter \"" + p.name + "\" is given twice (first at " + q.at.str() +
                           ")");
      std::vector<PbrtToken> values;
      if (in.peek().kind == PbrtToken::Kind::Open) {
        PbrtToken open = in.take();
        for (;;) {
          const PbrtToken& t = in.peek();
          if (t.kind == PbrtToken::Kind::Close) break;
          if (t.kind == PbrtToken::Kind::End || t.kind == PbrtToken::Kind::Open)
            throw InputError(open.at.str() + ": '[' of \"" + p.name + "\" is not closed (found " + describe(t) +
                             " at " + t.at.str() + ")");
          values.push_back(in.take());
        }
        in.take();
      } else {
        const PbrtToken& t = in.peek();
        if (t.kind != PbrtToken::Kind::Word && t.kind != PbrtToken::Kind::String)
          throw InputError(t.at.str() + ": \"" + p.type + " " + p.name + "\" needs a value, got " + describe(t));
        values.push_back(in.take());
      }
      if (values.empty()) throw InputError(decl.at.str() + ": \"" + p.type + " " + p.name + "\" has no values");
      fill(p, type, values);
      d.params.list.push_back(std::move(p));
    }
  }

  static void fill(PbrtParam& p, const std::string& type, const std::vector<PbrtToken>& values) {
    const std::string what = "a value of \"" + p.type + " " + p.name + "\"";
    if (type == "bool") {
      for (const PbrtToken& t : values) {
        if (t.text != "true" && t.text != "false")
          throw InputError(t.at.str() + ": " + what + " must be true or false, got " + describe(t));
        p.bools.push_back(t.text == "true");
      }
    } else if (type == "string" || type == "texture") {
      for (const PbrtToken& t : values) {
        if (t.kind != PbrtToken::Kind::String)
          throw InputError(t.at.str() + ": " + what + " must be a quoted string, got " + describe(t));
        p.strings.push_back(t.text);
      }
    } else if (type == "spectrum" && values[0].kind == PbrtToken::Kind::String) {
      if (values.size() != 1)
        throw InputError(values[1].at.str() + ": \"" + p.type + " " + p.name + "\" takes one spectrum name or file");
      p.strings.push_back(values[0].text);
    } else {
      for (const PbrtToken& t : values) p.numbers.push_back(number(t, what));
    }
  }

  std::vector<PbrtDirective>* out_;
  std::vector<fs::path> stack_;
};

}  // namespace

std::vector<PbrtDirective> parse_pbrt_file(const fs::path& file) {
  std::vector<PbrtDirective> out;
  Parser(&out).parse_file(file, file.string(), nullptr);
  return out;
}

std::vector<PbrtDirective> parse_pbrt_text(std::string_view text, const std::string& name, const fs::path& dir) {
  std::vector<PbrtDirective> out;
  Parser(&out).parse_text(text, name, dir);
  return out;
}

}  // namespace pdrt
