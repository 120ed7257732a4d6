#include "lang/parser.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "ncoffset/alarm.hpp"

namespace ncoffset::lang {
namespace {

bool isAlpha(char c) {
  return (c >= 'A' && c <= 'Z') || c == '_' || c == '$';
}
bool isDigit(char c) {
  return c >= '0' && c <= '9';
}
bool isIdentChar(char c) {
  return isAlpha(c) || isDigit(c);
}

// Up to eight characters packed into one integer (first character lowest), so that a name is
// looked up in a keyword list by one switch instead of string comparisons; names longer than
// eight characters pack to 0, which matches no keyword.
constexpr std::uint64_t packName(std::string_view w) {
  if (w.empty() || w.size() > 8) return 0;
  std::uint64_t v = 0;
  for (size_t i = 0; i < w.size(); ++i)
    v |= static_cast<std::uint64_t>(static_cast<unsigned char>(w[i])) << (8 * i);
  return v;
}

// Keywords that open or continue statements with their own syntax.
bool isControlKeyword(std::string_view w) {
  switch (packName(w)) {
    case packName("DEF"):
    case packName("IF"):
    case packName("ELSE"):
    case packName("ENDIF"):
    case packName("WHILE"):
    case packName("ENDWHILE"):
    case packName("FOR"):
    case packName("ENDFOR"):
    case packName("REPEAT"):
    case packName("UNTIL"):
    case packName("LOOP"):
    case packName("ENDLOOP"):
    case packName("GOTOF"):
    case packName("GOTOB"):
    case packName("GOTO"):
    case packName("GOTOC"):
    case packName("CASE"):
    case packName("PROC"):
      return true;
    default:
      return false;
  }
}

int jumpKind(std::string_view w) {
  if (w == "GOTOF") return 1;
  if (w == "GOTOB") return 2;
  if (w == "GOTO") return 3;
  if (w == "GOTOC") return 4;
  return 0;
}

// Exact powers of ten for Clinger's fast path (mantissa <= 15 digits divided by 10^decimals).
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

class Parser {
 public:
  // `text`: the normalised block, followed by a '\0' (see normalizeInto).
  Parser(Block& b, std::string_view text, const ParseLimits& limits)
      : b_(b), s_(text), limits_(limits) {}

  void parse() {
    skipSpaces();
    if (peek() == '/') {
      b_.skip = true;
      ++i_;
      if (isDigit(peek())) b_.skip_level = s_[i_++] - '0';
      skipSpaces();
    }
    if ((peek() == 'N' && isDigit(peek(1))) || (peek() == ':' && isDigit(peek(1)))) {
      ++i_;
      b_.has_number = true;
      b_.number = readInteger();
      skipSpaces();
    }
    // Label: identifier directly followed by ':'.
    if (isAlpha(peek())) {
      size_t j = i_;
      while (j < s_.size() && isIdentChar(s_[j])) ++j;
      if (j < s_.size() && s_[j] == ':' && j - i_ >= 2) {
        if (j - i_ > 32) syntax("labels have at most 32 characters");
        b_.label = std::string_view(s_).substr(i_, j - i_);
        i_ = j + 1;
      }
    }
    if (simpleWords()) return;
    generalStatements();
  }

  // parse() for a block as written (not normalised): only blocks the fast path takes entirely,
  // with at most a block number N.. in front (no skip level, label or anything that could
  // raise an alarm). False: nothing is decided, the block must be normalised and parsed.
  bool parseWritten() {
    skipSpaces();
    if (peek() == 'N' && isDigit(peek(1))) {
      size_t j = i_ + 1;
      while (j < s_.size() && isDigit(s_[j])) ++j;
      if (j - i_ - 1 > 18) return false;
      ++i_;
      b_.has_number = true;
      b_.number = readInteger();
    }
    return simpleWords();
  }

 private:
  void generalStatements() {
    while (true) {
      skipSpaces();
      if (i_ >= s_.size()) break;
      statement();
    }
  }

  Block& b_;
  const std::string_view s_;
  const ParseLimits& limits_;
  size_t i_ = 0;
  int depth_ = 0;

  char peek(size_t k = 0) const { return i_ + k < s_.size() ? s_[i_ + k] : '\0'; }
  void skipSpaces() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
  }
  int column() const { return static_cast<int>(i_) + 1; }

  [[noreturn]] void syntax(const std::string& what) const {
    std::string near(s_.substr(i_ < s_.size() ? i_ : s_.size(), 24));
    raise(AlarmNumber::SyntaxError,
          "syntax error in text at column " + std::to_string(column()) +
              (near.empty() ? std::string(" (end of block)") : " near '" + near + "'") + ": " +
              what);
  }

  void expect(char c, const char* what) {
    skipSpaces();
    if (peek() != c) syntax(std::string("expected ") + what);
    ++i_;
  }

  std::string_view ident() {
    size_t j = i_;
    while (j < s_.size() && isIdentChar(s_[j])) ++j;
    std::string_view v = std::string_view(s_).substr(i_, j - i_);
    i_ = j;
    return v;
  }

  long long readInteger() {
    long long v = 0;
    int digits = 0;
    while (isDigit(peek())) {
      if (++digits > 18) syntax("number too long");
      v = v * 10 + (s_[i_++] - '0');
    }
    return v;
  }

  int addNode(const Node& n) {
    b_.nodes.push_back(n);
    return static_cast<int>(b_.nodes.size()) - 1;
  }

  // Unsigned decimal literal with optional EX exponent (PM-NC: 1.5EX3 = 1500).
  int number(bool negative) {
    bool is_int;
    double v = scanNumber(is_int);
    Node n;
    n.kind = NodeKind::Number;
    n.number = negative ? -v : v;
    n.is_int = is_int;
    return addNode(n);
  }

  double scanNumber(bool& is_int_out) {
    const char* const begin = s_.data() + i_;
    const char* const end = s_.data() + s_.size();
    const char* p = begin;
    // Mantissa and decimals in one pass (Clinger's fast path: exact for <= 15 significant
    // digits and <= 22 decimals; anything longer goes through std::from_chars).
    unsigned long long mant = 0;
    int significant = 0;
    while (p < end && isDigit(*p)) {
      mant = mant * 10 + static_cast<unsigned>(*p - '0');
      significant += (mant != 0);
      ++p;
    }
    bool is_int = true;
    int decimals = 0;
    if (p < end && *p == '.') {
      is_int = false;
      ++p;
      while (p < end && isDigit(*p)) {
        mant = mant * 10 + static_cast<unsigned>(*p - '0');
        significant += (mant != 0);
        ++decimals;
        ++p;
      }
    }
    size_t len = static_cast<size_t>(p - begin);
    if (len == 0 || (len == 1 && *begin == '.')) syntax("number expected");
    if (len > 21) syntax("number with too many digits (at most 20)");
    double v;
    if (significant <= 15 && decimals <= 22) {
      v = static_cast<double>(mant) / kPow10[decimals];
    } else {
      auto res = std::from_chars(begin, p, v);
      if (res.ec != std::errc()) syntax("number out of range");
    }
    i_ += len;
    if (peek() == 'E' && peek(1) == 'X') {
      size_t save = i_;
      i_ += 2;
      bool neg = false;
      if (peek() == '-' || peek() == '+') neg = s_[i_++] == '-';
      if (!isDigit(peek())) {
        i_ = save;
      } else {
        long long e = readInteger();
        if (e > 400) e = 400;
        v *= std::pow(10.0, static_cast<double>(neg ? -e : e));
        is_int = false;
        if (!std::isfinite(v)) syntax("number out of range");
      }
    }
    is_int_out = is_int;
    return v;
  }

  // Fast path for the blocks CAM systems write (`G1 X10.5 Y-2 F1000`, `G3 X5 Y5 CR=10`): only
  // address words with a plain number, single letters (X10) or extended addresses with '='
  // (CR=10). It makes the same statements the general path makes for these words; at the first
  // thing it does not know it drops what it made and returns false, and the general path parses
  // the block from the same position (and reports any error).
  bool simpleWords() {
    // A '\0' follows the block's last character (normalizeInto lets no other '\0' through),
    // which ends every scan below without a length check.
    const char* const base = s_.data();
    const char* p = base + i_;
    const size_t first = b_.stmts.size();
    auto isBlank = [](char c) { return c == ' ' || c == '\t'; };
    auto isLetter = [](char c) { return c >= 'A' && c <= 'Z'; };
    auto give_up = [&] {
      b_.stmts.resize(first);
      return false;
    };
    while (isBlank(*p)) ++p;
    while (*p != '\0') {
      const char* const word = p;
      if (!isLetter(*p)) return give_up();
      ++p;
      while (isLetter(*p)) ++p;
      const std::string_view name(word, static_cast<size_t>(p - word));
      const bool equals = name.size() > 1;
      if (equals) {
        // CR=10: an extended address directly followed by '=' (no '==').
        if (*p != '=' || p[1] == '=' || !isExtendedAddress(name)) return give_up();
        ++p;
      }
      bool negative = false;
      if (*p == '-' || *p == '+') negative = *p++ == '-';
      // Digits with at most one point, converted as scanNumber converts them (at most 15
      // digits: Clinger's fast path).
      const char* const digits = p;
      unsigned long long mant = 0;
      while (isDigit(*p)) mant = mant * 10 + static_cast<unsigned>(*p++ - '0');
      const char* point = p;
      if (*p == '.') {
        ++p;
        while (isDigit(*p)) mant = mant * 10 + static_cast<unsigned>(*p++ - '0');
      }
      const bool is_int = *point != '.';
      const auto count = static_cast<size_t>(p - digits) - (is_int ? 0 : 1);
      if (count == 0 || count > 15) return give_up();
      const int decimals = is_int ? 0 : static_cast<int>(p - point - 1);
      // What may follow: the end, a blank, or (single letters only: G1X10) the next address
      // but not an exponent (1EX3). After single letters a '=' makes an assignment (R1=5,
      // M2=6, I1=5).
      const char* next = p;
      while (isBlank(*next)) ++next;
      if (equals) {
        if (next == p && *p != '\0') return give_up();
      } else {
        if (next == p && *p != '\0' && (!isLetter(*p) || (p[0] == 'E' && p[1] == 'X')))
          return give_up();
        if (*next == '=' || (*word == 'R' && isDigit(word[1]))) return give_up();
      }
      // At most 15 digits: the mantissa converts exactly, as a signed number (one instruction);
      // whole numbers need no division.
      const auto whole = static_cast<double>(static_cast<long long>(mant));
      const double v = decimals == 0 ? whole : whole / kPow10[decimals];
      Stmt st;
      st.kind = StmtKind::Word;
      st.name = name;
      st.column = static_cast<int>(word - base) + 1;
      st.has_equals = equals;
      st.literal = true;
      st.literal_int = is_int;
      st.literal_value = negative ? -v : v;
      b_.stmts.push_back(st);
      p = next;
    }
    if (p != base + s_.size()) return give_up();  // a '\0' inside the block (not normalised)
    i_ = s_.size();
    return true;
  }

  // 'H1F' hexadecimal and 'B101' binary constants.
  int quotedConstant() {
    ++i_;  // '
    char base = peek();
    if (base != 'H' && base != 'B') syntax("'H..' or 'B..' constant expected");
    ++i_;
    size_t start = i_;
    while (i_ < s_.size() && s_[i_] != '\'') ++i_;
    if (i_ >= s_.size()) syntax("unterminated constant");
    unsigned long long v = 0;
    auto res = std::from_chars(s_.data() + start, s_.data() + i_, v, base == 'H' ? 16 : 2);
    if (res.ec != std::errc() || res.ptr != s_.data() + i_) syntax("invalid constant");
    ++i_;
    Node n;
    n.kind = NodeKind::Number;
    n.number = static_cast<double>(v);
    n.is_int = true;
    return addNode(n);
  }

  int stringLiteral() {
    ++i_;  // "
    size_t start = i_;
    while (i_ < s_.size() && s_[i_] != '"') ++i_;
    if (i_ >= s_.size()) syntax("unterminated string");
    Node n;
    n.kind = NodeKind::String;
    n.text = std::string_view(s_).substr(start, i_ - start);
    ++i_;
    return addNode(n);
  }

  // Argument list after '(' or '['; returns first index into args and count.
  std::pair<int, int> argList(char close) {
    std::vector<int> tmp;
    skipSpaces();
    if (peek() == close) {
      ++i_;
      return {static_cast<int>(b_.args.size()), 0};
    }
    while (true) {
      skipSpaces();
      if (peek() == ',' || peek() == close) {
        // Empty argument (optional parameter left out).
        Node n;
        n.kind = NodeKind::Name;
        tmp.push_back(addNode(n));
      } else {
        tmp.push_back(expression());
      }
      skipSpaces();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      if (peek() == close) {
        ++i_;
        break;
      }
      syntax(close == ')' ? "expected ',' or ')'" : "expected ',' or ']'");
    }
    int first = static_cast<int>(b_.args.size());
    b_.args.insert(b_.args.end(), tmp.begin(), tmp.end());
    return {first, static_cast<int>(tmp.size())};
  }

  int primary() {
    skipSpaces();
    char c = peek();
    if (isDigit(c) || (c == '.' && isDigit(peek(1)))) return number(false);
    if (c == '"') return stringLiteral();
    if (c == '\'') return quotedConstant();
    if (c == '(') {
      ++i_;
      int e = expression();
      expect(')', "')'");
      return e;
    }
    if (isAlpha(c)) {
      std::string_view name = ident();
      if (name == "TRUE" || name == "FALSE") {
        Node n;
        n.kind = NodeKind::Bool;
        n.number = name == "TRUE" ? 1 : 0;
        return addNode(n);
      }
      if (isRParamName(name)) {
        Node n;
        n.kind = NodeKind::RParam;
        n.number = parseDigits(name.substr(1));
        return addNode(n);
      }
      skipSpaces();
      if (peek() == '(' || peek() == '[') {
        char open = peek();
        ++i_;
        auto [first, count] = argList(open == '(' ? ')' : ']');
        Node n;
        n.kind = open == '(' ? NodeKind::Call : NodeKind::Index;
        if (open == '[' && name == "R") n.kind = NodeKind::RIndex;
        n.text = name;
        n.a = first;
        n.b = count;
        return addNode(n);
      }
      Node n;
      n.kind = NodeKind::Name;
      n.text = name;
      return addNode(n);
    }
    syntax("operand expected");
  }

  // R1, R99: an R parameter written as a name.
  static bool isRParamName(std::string_view v) {
    return v.size() >= 2 && v[0] == 'R' && isDigitsOnly(v.substr(1));
  }
  static bool isDigitsOnly(std::string_view v) {
    if (v.empty()) return false;
    for (char c : v)
      if (!isDigit(c)) return false;
    return true;
  }
  double parseDigits(std::string_view v) const {
    if (v.size() > 9) syntax("R parameter number too large");
    double r = 0;
    for (char c : v) r = r * 10 + (c - '0');
    return r;
  }

  int unary() {
    skipSpaces();
    char c = peek();
    Op op = Op::None;
    if (c == '-') {
      op = Op::Neg;
      ++i_;
    } else if (c == '+') {
      op = Op::Plus;
      ++i_;
    } else if (wordAhead("NOT")) {
      op = Op::Not;
      i_ += 3;
    } else if (wordAhead("B_NOT")) {
      op = Op::BNot;
      i_ += 5;
    }
    if (op == Op::None) return primary();
    enter();
    int operand = unary();
    leave();
    Node n;
    n.kind = NodeKind::Unary;
    n.op = op;
    n.a = operand;
    return addNode(n);
  }

  bool wordAhead(std::string_view w) const {
    if (s_.compare(i_, w.size(), w) != 0) return false;
    size_t j = i_ + w.size();
    return j >= s_.size() || !isIdentChar(s_[j]);
  }

  // Binary operator at the current position and its priority (PM-NC 12/2019 p444: higher binds
  // tighter; comparisons bind weakest, then the frame chain ':').
  bool binaryOp(Op& op, int& prio, size_t& len) const {
    char c = peek(), d = peek(1);
    len = 1;
    switch (c) {
      case '*':
        op = Op::Mul;
        prio = 10;
        return true;
      case '/':
        op = Op::Div;
        prio = 10;
        return true;
      case '+':
        op = Op::Add;
        prio = 9;
        return true;
      case '-':
        op = Op::Sub;
        prio = 9;
        return true;
      case '=':
        if (d == '=') {
          op = Op::Eq;
          prio = 1;
          len = 2;
          return true;
        }
        return false;
      case '<':
        if (d == '>') {
          op = Op::Ne;
          prio = 1;
          len = 2;
          return true;
        }
        if (d == '=') {
          op = Op::Le;
          prio = 1;
          len = 2;
          return true;
        }
        if (d == '<') {
          op = Op::Concat;
          prio = 2;
          len = 2;
          return true;
        }
        op = Op::Lt;
        prio = 1;
        return true;
      case '>':
        if (d == '=') {
          op = Op::Ge;
          prio = 1;
          len = 2;
          return true;
        }
        if (d == '<') {
          op = Op::Ne;
          prio = 1;
          len = 2;
          return true;
        }
        op = Op::Gt;
        prio = 1;
        return true;
      case ':':
        op = Op::Chain;
        prio = 0;
        return true;
      default:
        break;
    }
    struct W {
      std::string_view w;
      Op op;
      int prio;
    };
    static constexpr W kWords[] = {{"DIV", Op::IntDiv, 10}, {"MOD", Op::Mod, 10},
                                   {"B_AND", Op::BAnd, 8},  {"B_XOR", Op::BXor, 7},
                                   {"B_OR", Op::BOr, 6},    {"AND", Op::And, 5},
                                   {"XOR", Op::Xor, 4},     {"OR", Op::Or, 3}};
    if (!isAlpha(c)) return false;
    for (const W& w : kWords) {
      if (wordAhead(w.w)) {
        op = w.op;
        prio = w.prio;
        len = w.w.size();
        return true;
      }
    }
    return false;
  }

  void enter() {
    if (++depth_ > limits_.max_expression_depth)
      raise(AlarmNumber::ExpressionDepth, "expression nested deeper than the limit of " +
                                              std::to_string(limits_.max_expression_depth) +
                                              " (--max-expression-depth)");
  }
  void leave() { --depth_; }

  int binary(int min_prio) {
    enter();
    int left = unary();
    while (true) {
      skipSpaces();
      Op op;
      int prio;
      size_t len;
      if (!binaryOp(op, prio, len) || prio < min_prio) break;
      i_ += len;
      int right = binary(prio + 1);
      Node n;
      n.kind = NodeKind::Binary;
      n.op = op;
      n.a = left;
      n.b = right;
      left = addNode(n);
    }
    leave();
    return left;
  }

 public:
  int expression() { return binary(0); }

 private:
  // --- statements ---------------------------------------------------------------------------

  void statement() {
    int col = column();
    char c = peek();
    if (!isAlpha(c)) {
      if (c == '=') syntax("address or variable expected before '='");
      syntax("address or name expected");
    }
    // Single-letter address followed by a plain number: X10, G1, M30, X-5.5, T1, D1, R1=..
    char n1 = peek(1);
    if (c != '$' && c != '_' &&
        (isDigit(n1) ||
         ((n1 == '.' || n1 == '-' || n1 == '+') && (isDigit(peek(2)) || peek(2) == '.')))) {
      numericAddress(col);
      return;
    }
    std::string_view name = ident();
    skipSpaces();
    if (isControlKeyword(name)) {
      controlStatement(name, col);
      return;
    }
    if (peek() == '=' && peek(1) != '=') {
      const bool address = isExtendedAddress(name);
      if (address && literalWord(name, col)) return;
      ++i_;
      int value = expression();
      if (address) {
        addWord(name, -1, value, col, true);
      } else {
        Node t;
        t.kind = NodeKind::Name;
        t.text = name;
        Stmt st;
        st.kind = StmtKind::Assign;
        st.name = name;
        st.target = addNode(t);
        st.expr = value;
        st.column = col;
        b_.stmts.push_back(st);
      }
      return;
    }
    if (peek() == '[') {
      ++i_;
      auto [first, count] = argList(']');
      Node t;
      t.kind = name == "R" ? NodeKind::RIndex : NodeKind::Index;
      t.text = name;
      t.a = first;
      t.b = count;
      int target = addNode(t);
      skipSpaces();
      if (peek() != '=' || peek(1) == '=') syntax("'=' expected after indexed variable");
      ++i_;
      Stmt st;
      st.kind = StmtKind::Assign;
      st.name = name;
      st.target = target;
      st.expr = expression();
      st.column = col;
      b_.stmts.push_back(st);
      return;
    }
    if (peek() == '(') {
      ++i_;
      auto [first, count] = argList(')');
      Node call;
      call.kind = NodeKind::Call;
      call.text = name;
      call.a = first;
      call.b = count;
      Stmt st;
      st.kind = StmtKind::ProcCall;
      st.name = name;
      st.expr = addNode(call);
      st.column = col;
      b_.stmts.push_back(st);
      return;
    }
    // Programs are called by names of at least two characters (PM-NC 12/2019 p491): a lone
    // letter is an address whose value is missing.
    if (name.size() == 1) syntax(std::string("value missing after address ") + name[0]);
    Stmt st;
    st.kind = StmtKind::Call;
    st.name = name;
    st.column = col;
    b_.stmts.push_back(st);
  }

  // `CR=10`, `DISR=-5.5`: an address with '=' and a plain number, the common case, kept as a
  // literal word without an expression node (the same statement the expression path makes, only
  // cheaper). Anything else (an operator, a function, 1EX3, AC(..)) takes the expression path.
  bool literalWord(std::string_view name, int col) {
    const size_t save = i_;
    ++i_;  // '='
    bool negative = false;
    if (peek() == '-' || peek() == '+') negative = s_[i_++] == '-';
    if (!(isDigit(peek()) || (peek() == '.' && isDigit(peek(1))))) {
      i_ = save;
      return false;
    }
    bool is_int = false;
    const double v = scanNumber(is_int);
    size_t j = i_;
    while (j < s_.size() && s_[j] == ' ') ++j;
    const bool ends = j == s_.size() || s_[j] == ';' || (j > i_ && isAlpha(s_[j]));
    if (!ends) {
      i_ = save;
      return false;
    }
    Stmt& st = b_.stmts.emplace_back(wordStmt(name, col, true));
    st.literal = true;
    st.literal_int = is_int;
    st.literal_value = negative ? -v : v;
    return true;
  }

  static bool isExtendedAddress(std::string_view name) {
    if (name.size() == 1) return name[0] != '$' && name[0] != '_';
    switch (packName(name)) {
      case packName("CR"):
      case packName("AR"):
      case packName("TURN"):
      case packName("DISR"):
      case packName("DISC"):
      case packName("OFFN"):
      case packName("DISCL"):
      case packName("DISRP"):
      case packName("FAD"):
      case packName("RPL"):
      case packName("RND"):
      case packName("RNDM"):
      case packName("CHF"):
      case packName("CHR"):
      case packName("SPOS"):
      case packName("SPOSA"):
      case packName("FRC"):
      case packName("FRCM"):
      case packName("ANG"):
      case packName("AP"):
      case packName("RP"):
      case packName("DISPR"):
      case packName("I1"):
      case packName("J1"):
      case packName("K1"):
      case packName("CT"):
      case packName("SF"):
      case packName("FA"):
      case packName("POS"):
      case packName("POSA"):
      case packName("ACC"):
      case packName("OVR"):
      case packName("LIMS"):
      case packName("MOVT"):
      case packName("PM"):
      case packName("PR"):
      case packName("STOLF"):
      case packName("DITS"):
      case packName("DITE"):
      case packName("SCC"):
        return true;
      default:
        return false;
    }
  }

  static Stmt wordStmt(std::string_view address, int col, bool equals) {
    Stmt st;
    st.kind = StmtKind::Word;
    st.name = address;
    st.column = col;
    st.has_equals = equals;
    return st;
  }

  void addWord(std::string_view address, int ext, int value, int col, bool equals) {
    Stmt st = wordStmt(address, col, equals);
    st.ext = ext;
    st.expr = value;
    // X=AC(..) / X=IC(..): absolute or incremental dimension for this word only.
    const Node& v = b_.node(value);
    if (v.kind == NodeKind::Call && (v.text == "AC" || v.text == "IC")) {
      if (v.b != 1) syntax("AC/IC take one value");
      st.mode = v.text == "AC" ? AxisMode::AC : AxisMode::IC;
      st.expr = b_.arg(v, 0);
    }
    b_.stmts.push_back(st);
  }

  void numericAddress(int col) {
    std::string_view address = std::string_view(s_).substr(i_, 1);
    ++i_;
    // The common word (X10, G1, F1000, T1 D1): digits not followed by '=' and no R parameter;
    // one scan decides it. Longer digit runs take the paths below, which report them.
    if (address[0] != 'R') {
      size_t j = i_;
      while (j < s_.size() && isDigit(s_[j])) ++j;
      size_t k = j;
      while (k < s_.size() && (s_[k] == ' ' || s_[k] == '\t')) ++k;
      const bool assignment =
          k < s_.size() && s_[k] == '=' && !(k + 1 < s_.size() && s_[k + 1] == '=');
      if (j - i_ <= 18 && !assignment) {
        plainWord(address, col);
        return;
      }
    }
    // R parameter assignment R1=..
    if (address == "R" && isDigit(peek())) {
      size_t start = i_;
      while (isDigit(peek())) ++i_;
      std::string_view digits = std::string_view(s_).substr(start, i_ - start);
      skipSpaces();
      if (peek() != '=' || peek(1) == '=') syntax("'=' expected after R parameter");
      ++i_;
      Node t;
      t.kind = NodeKind::RParam;
      t.number = parseDigits(digits);
      Stmt st;
      st.kind = StmtKind::Assign;
      st.name = "R";
      st.target = addNode(t);
      st.expr = expression();
      st.column = col;
      b_.stmts.push_back(st);
      return;
    }
    // Address extension: M2=6, S1=1000, H2=5, T1=..? (spindle / extension number).
    if ((address == "M" || address == "S" || address == "H" || address == "T" || address == "D" ||
         address == "F") &&
        isDigit(peek())) {
      size_t save = i_;
      long long ext = readInteger();
      skipSpaces();
      if (peek() == '=' && peek(1) != '=') {
        ++i_;
        if (ext > 99) syntax("address extension too large");
        addWord(address, static_cast<int>(ext), expression(), col, true);
        return;
      }
      i_ = save;
    }
    // Address with a numeric suffix and '=': I1=, J1=, K1= (CIP intermediate point) and similar.
    if (isDigit(peek())) {
      size_t save = i_;
      while (isDigit(peek())) ++i_;
      size_t end = i_;
      skipSpaces();
      if (peek() == '=' && peek(1) != '=') {
        ++i_;
        addWord(std::string_view(s_).substr(save - 1, end - save + 1), -1, expression(), col, true);
        return;
      }
      i_ = save;
    }
    plainWord(address, col);
  }

  // The common plain word (X10, G1, F1000, X-5.5) keeps its value in the statement: no node.
  void plainWord(std::string_view address, int col) {
    bool negative = false;
    if (peek() == '-' || peek() == '+') negative = s_[i_++] == '-';
    bool is_int = false;
    const double v = scanNumber(is_int);
    Stmt& st = b_.stmts.emplace_back();
    st.kind = StmtKind::Word;
    st.name = address;
    st.column = col;
    st.literal = true;
    st.literal_int = is_int;
    st.literal_value = negative ? -v : v;
    // A letter may follow directly (G1X10Y20); anything else must be a separator.
    if (isDigit(peek())) syntax("unexpected digit");
  }

  int jumpTarget() {
    skipSpaces();
    if ((peek() == 'N' && isDigit(peek(1))) || (peek() == ':' && isDigit(peek(1)))) {
      ++i_;
      Node n;
      n.kind = NodeKind::BlockNo;
      n.number = static_cast<double>(readInteger());
      return addNode(n);
    }
    if (isDigit(peek())) {
      Node n;
      n.kind = NodeKind::BlockNo;
      n.number = static_cast<double>(readInteger());
      return addNode(n);
    }
    if (!isAlpha(peek()) && peek() != '"') syntax("jump destination expected");
    return expression();
  }

  void controlStatement(std::string_view kw, int col) {
    Stmt st;
    st.kind = StmtKind::Keyword;
    st.name = kw;
    st.column = col;
    if (kw == "DEF") {
      definition(col);
      return;
    }
    if (kw == "IF" || kw == "WHILE" || kw == "UNTIL") {
      st.expr = expression();
      b_.stmts.push_back(st);
      return;
    }
    if (int j = jumpKind(kw)) {
      st.jump = j;
      st.target = jumpTarget();
      b_.stmts.push_back(st);
      skipSpaces();
      if (i_ < s_.size()) syntax("nothing may follow the jump destination in its block");
      return;
    }
    if (kw == "FOR") {
      skipSpaces();
      if (!isAlpha(peek())) syntax("loop variable expected after FOR");
      std::string_view var = ident();
      Node t;
      if (isRParamName(var)) {
        t.kind = NodeKind::RParam;
        t.number = parseDigits(var.substr(1));
      } else {
        t.kind = NodeKind::Name;
        t.text = var;
      }
      st.target = addNode(t);
      expect('=', "'=' after the FOR variable");
      st.expr = expression();
      skipSpaces();
      if (!wordAhead("TO")) syntax("TO expected in FOR");
      i_ += 2;
      st.expr2 = expression();
      b_.stmts.push_back(st);
      return;
    }
    if (kw == "CASE") {
      expect('(', "'(' after CASE");
      st.expr = expression();
      expect(')', "')'");
      skipSpaces();
      if (!wordAhead("OF")) syntax("OF expected in CASE");
      i_ += 2;
      b_.stmts.push_back(st);
      caseArms();
      return;
    }
    if (kw == "PROC") {
      skipSpaces();
      if (!isAlpha(peek())) syntax("program name expected after PROC");
      std::string_view name = ident();
      Node n;
      n.kind = NodeKind::Name;
      n.text = name;
      st.target = addNode(n);
      skipSpaces();
      if (peek() == '(') {
        // Formal parameters (e.g. `REAL LEN, VAR INT N`): counted, not parsed further.
        ++i_;
        int depth = 1, count = 0;
        bool any = false;
        while (i_ < s_.size() && depth > 0) {
          char ch = s_[i_++];
          if (ch == '(')
            ++depth;
          else if (ch == ')')
            --depth;
          else if (ch == ',' && depth == 1)
            ++count;
          else if (ch != ' ')
            any = true;
        }
        if (depth != 0) syntax("')' expected after the PROC parameters");
        st.ext = any ? count + 1 : 0;
      }
      b_.stmts.push_back(st);
      // Attributes such as SAVE or DISPLOF may follow; they are kept as calls.
      return;
    }
    b_.stmts.push_back(st);  // ELSE, ENDIF, ENDWHILE, ENDFOR, REPEAT, LOOP, ENDLOOP
  }

  void caseArms() {
    while (true) {
      skipSpaces();
      if (i_ >= s_.size()) return;
      Stmt arm;
      arm.kind = StmtKind::CaseArm;
      arm.column = column();
      if (wordAhead("DEFAULT")) {
        i_ += 7;
        arm.expr = -1;
      } else {
        arm.expr = unary();
      }
      skipSpaces();
      if (!isAlpha(peek())) syntax("GOTOF/GOTOB expected in CASE");
      std::string_view kw = ident();
      arm.jump = jumpKind(kw);
      if (!arm.jump) syntax("GOTOF/GOTOB expected in CASE");
      arm.name = kw;
      arm.target = jumpTarget();
      b_.stmts.push_back(arm);
    }
  }

  static bool typeOf(std::string_view w, VarType& t) {
    if (w == "INT")
      t = VarType::Int;
    else if (w == "REAL")
      t = VarType::Real;
    else if (w == "BOOL")
      t = VarType::Bool;
    else if (w == "STRING")
      t = VarType::String;
    else if (w == "CHAR")
      t = VarType::Char;
    else if (w == "AXIS")
      t = VarType::Axis;
    else if (w == "FRAME")
      t = VarType::Frame;
    else
      return false;
    return true;
  }

  void definition(int col) {
    skipSpaces();
    std::string_view w = ident();
    if (w == "NCK" || w == "CHAN") {  // global user data: same handling in one channel
      skipSpaces();
      w = ident();
    }
    VarType type;
    if (!typeOf(w, type))
      syntax("data type expected after DEF (INT, REAL, BOOL, STRING, CHAR, AXIS, FRAME)");
    int string_length = 0;
    skipSpaces();
    if (type == VarType::String) {
      if (peek() != '[') syntax("STRING needs a length: STRING[n]");
      ++i_;
      skipSpaces();
      if (!isDigit(peek())) syntax("string length expected");
      long long len = readInteger();
      if (len < 1 || len > 200) syntax("string length must be 1..200");
      string_length = static_cast<int>(len);
      expect(']', "']'");
    }
    while (true) {
      skipSpaces();
      if (!isAlpha(peek())) syntax("variable name expected in DEF");
      Decl d;
      d.type = type;
      d.string_length = string_length;
      d.column = column();
      d.name = ident();
      if (d.name.size() > 32) syntax("variable names have at most 32 characters");
      skipSpaces();
      if (peek() == '[') {
        ++i_;
        for (int k = 0; k < 3; ++k) {
          skipSpaces();
          if (!isDigit(peek())) syntax("array size must be a number");
          long long n = readInteger();
          if (k == 2) syntax("arrays have at most two dimensions");
          if (n < 1 || n > 1000000000) syntax("array size out of range");
          d.dims[k] = static_cast<int>(n);
          skipSpaces();
          if (peek() == ',') {
            ++i_;
            continue;
          }
          break;
        }
        expect(']', "']'");
      }
      skipSpaces();
      if (peek() == '=' && peek(1) != '=') {
        ++i_;
        skipSpaces();
        if (d.dims[0] > 0) {
          bool rep = wordAhead("REP");
          if (wordAhead("SET") || rep) {
            i_ += 3;
            expect('(', "'('");
          } else if (peek() == '(') {
            ++i_;
          } else {
            syntax("array initialisation needs SET(..), REP(..) or (..)");
          }
          auto [first, count] = argList(')');
          d.init_first = first;
          d.init_count = count;
          d.init_rep = rep;
        } else {
          d.init = expression();
        }
      }
      b_.decls.push_back(d);
      skipSpaces();
      if (peek() == ',') {
        ++i_;
        continue;
      }
      break;
    }
    skipSpaces();
    if (i_ < s_.size()) syntax("unexpected text after DEF");
    Stmt st;
    st.kind = StmtKind::Keyword;
    st.name = "DEF";
    st.column = col;
    b_.stmts.push_back(st);
  }
};

}  // namespace

namespace {
// Byte classes for normalizeLine: 0 = not allowed outside strings/comments, 1 = copy as is,
// 2 = ';' (comment starts), 3 = '"' (string starts), 4 = white space to blank.
struct ByteTable {
  unsigned char cls[256];
  char upper[256];
  constexpr ByteTable() : cls(), upper() {
    for (int c = 0; c < 256; ++c) {
      cls[c] = (c >= 32 && c <= 126) ? 1 : 0;
      upper[c] = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    }
    cls[static_cast<int>(';')] = 2;
    cls[static_cast<int>('"')] = 3;
    for (int c : {'\t', '\r', '\f', '\v'}) {
      cls[c] = 4;
      upper[c] = ' ';
    }
  }
};
constexpr ByteTable kBytes;
}  // namespace

namespace {
// normalizeLine into `out` without shrinking it (a std::string that only grows is resized once,
// not for every block): sets `len` to the normalised length (up to a bad byte, for which it
// returns false) and, when it succeeds, puts a '\0' after it, which the parser's fast path
// relies on.
bool normalizeInto(std::string_view text, std::string& out, size_t& len, int* bad_column) {
  const size_t n = text.size();
  if (out.size() < n + 1) out.resize(n + 1);
  char* const begin = out.data();
  char* dst = begin;
  size_t k = 0;
  // Eight bytes at a time while they are plain upper-case text (0x20..0x5F, no ';' or '"').
  constexpr std::uint64_t kOnes = 0x0101010101010101ULL, kHigh = 0x8080808080808080ULL;
  auto hasLess = [](std::uint64_t x, unsigned n) { return (x - kOnes * n) & ~x & kHigh; };
  auto hasZero = [](std::uint64_t x) { return (x - kOnes) & ~x & kHigh; };
  auto plain = [&](size_t at, std::uint64_t& w) {
    std::memcpy(&w, text.data() + at, 8);
    return !(hasLess(w, 0x20) || ((w + kOnes * (0x80 - 0x60)) | w) & kHigh ||
             hasZero(w ^ (kOnes * ';')) || hasZero(w ^ (kOnes * '"')));
  };
  while (k + 8 <= n) {
    std::uint64_t w;
    if (!plain(k, w)) break;
    std::memcpy(dst, &w, 8);
    dst += 8;
    k += 8;
  }
  // The rest of a plain line as one more (overlapping) group of eight.
  if (k < n && n >= 8 && k + 8 > n) {
    std::uint64_t w;
    if (plain(n - 8, w)) {
      std::memcpy(begin + (n - 8), &w, 8);
      begin[n] = '\0';
      len = n;
      return true;
    }
  }
  while (k < n) {
    auto c = static_cast<unsigned char>(text[k]);
    switch (kBytes.cls[c]) {
      case 1:
      case 4:
        *dst++ = kBytes.upper[c];
        ++k;
        continue;
      case 2:
        k = n;
        continue;  // comment: the rest of the line
      case 3: {
        *dst++ = '"';
        ++k;
        while (k < n && text[k] != '"') {
          if (text[k] == '\0') {
            if (bad_column) *bad_column = static_cast<int>(k) + 1;
            len = static_cast<size_t>(dst - begin);
            return false;
          }
          *dst++ = text[k++];
        }
        if (k < n) *dst++ = text[k++];
        continue;
      }
      default:
        if (bad_column) *bad_column = static_cast<int>(k) + 1;
        len = static_cast<size_t>(dst - begin);
        return false;
    }
  }
  *dst = '\0';
  len = static_cast<size_t>(dst - begin);
  return true;
}
}  // namespace

bool normalizeLine(std::string_view text, std::string& out, int* bad_column) {
  size_t len = 0;
  const bool ok = normalizeInto(text, out, len, bad_column);
  out.resize(len);
  return ok;
}

void parseBlock(std::string_view text, int line, Block& out, const ParseLimits& limits) {
  out.clear();
  out.line = line;
  // Most blocks of CAM programs (N10 G1 X10.5 Y2 F1000) are plain upper-case words, which
  // normalising would leave as they are: the fast path tries the block as written first.
  const size_t n = text.size();
  if (out.buffer.size() < n + 1) out.buffer.resize(n + 1);
  char* const copy = out.buffer.data();
  if (n >= 8 && n <= 16) {  // the usual length: two (overlapping) groups of eight, no call
    std::memcpy(copy, text.data(), 8);
    std::memcpy(copy + n - 8, text.data() + n - 8, 8);
  } else {
    std::memcpy(copy, text.data(), n);
  }
  copy[n] = '\0';
  if (Parser(out, std::string_view(out.buffer.data(), n), limits).parseWritten()) return;
  out.clear();
  out.line = line;
  int bad = 0;
  size_t len = 0;
  if (!normalizeInto(text, out.buffer, len, &bad)) {
    unsigned char c = static_cast<unsigned char>(text[static_cast<size_t>(bad - 1)]);
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", c);
    raise(AlarmNumber::BadCharacter, "character " + std::string(hex) + " at column " +
                                         std::to_string(bad) +
                                         " is not allowed outside comments and strings");
  }
  Parser p(out, std::string_view(out.buffer.data(), len), limits);
  p.parse();
}

LineHead scanLineHead(std::string_view s) {
  LineHead h;
  size_t i = 0;
  auto spaces = [&] {
    while (i < s.size() && s[i] == ' ') ++i;
  };
  spaces();
  if (i < s.size() && s[i] == '/') {
    ++i;
    if (i < s.size() && isDigit(s[i])) ++i;
    spaces();
  }
  if (i + 1 < s.size() && (s[i] == 'N' || s[i] == ':') && isDigit(s[i + 1])) {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i;
    spaces();
  }
  size_t j = i;
  while (j < s.size() && isIdentChar(s[j])) ++j;
  if (j < s.size() && s[j] == ':' && j - i >= 2 && isAlpha(s[i])) {
    h.label = s.substr(i, j - i);
    i = j + 1;
    spaces();
    j = i;
    while (j < s.size() && isIdentChar(s[j])) ++j;
  }
  if (i < s.size() && isAlpha(s[i])) h.keyword = s.substr(i, j - i);
  if (h.keyword == "IF") {
    // IF <cond> GOTOx <target> is a conditional jump, not a structure.
    for (size_t k = j; k + 4 <= s.size(); ++k) {
      if (s.compare(k, 4, "GOTO") == 0 && (k == 0 || !isIdentChar(s[k - 1]))) {
        size_t e = k + 4;
        if (e < s.size() && (s[e] == 'F' || s[e] == 'B' || s[e] == 'C')) ++e;
        if (e >= s.size() || !isIdentChar(s[e])) {
          h.has_goto = true;
          break;
        }
      }
    }
  }
  return h;
}

}  // namespace ncoffset::lang
