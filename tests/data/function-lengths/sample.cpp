// The brace-matching heuristic of tools/function-lengths.py on the constructs it must get right
// (tests/CMakeLists.txt checks its report); not compiled.
// clang-format off
#include <string>
#define BRACES() { {
namespace ns {
// a comment with { braces
struct S {
  int a_;
  S(int a) : a_(a) {
    const char* s = "{ not a brace";
    (void)s;
  }
  int get() const { return a_; }
 public:
  void raw() {
    const char* r = R"x({ } }")x";
    char c = '{';
    (void)r, (void)c;
  }
};
auto lam = [](int x) {
  return x + 1;
};
template <class T>
T twice(T t) {
  auto f = [&]() { return t; };
  if (t) {
    return f() + f();
  }
  return t;
}
int braced_init() {
  int v[2] = {1, 2};
  return v[0];
}
}  // namespace ns
