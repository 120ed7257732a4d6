// One parsed NC block (PM-NC "Program structure"): its words, assignments and statements in
// the order written, and the expression nodes they refer to. A Block is reused from block to
// block so that parsing does not allocate in the steady state.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ncoffset::lang {

enum class NodeKind : std::uint8_t {
  Number,  // numeric literal (value in `number`; `is_int` when written without a point)
  Bool,    // TRUE / FALSE
  String,  // "text" (text without quotes)
  Name,    // identifier: variable, or a symbol such as an axis name in `$P_UIFR[1,X,TR]`
  Index,   // name[args]
  Call,    // name(args)
  RParam,  // R<n> with n in `number`
  RIndex,  // R[expr] (args: one)
  Unary,
  Binary,
  BlockNo,  // jump target N<n> or :<n>, number in `number`
};

enum class Op : std::uint8_t {
  None,
  Neg,
  Plus,
  Not,
  BNot,
  Add,
  Sub,
  Mul,
  Div,
  IntDiv,
  Mod,
  BAnd,
  BXor,
  BOr,
  And,
  Xor,
  Or,
  Concat,
  Eq,
  Ne,
  Lt,
  Gt,
  Le,
  Ge,
  Chain,
};

struct Node {
  NodeKind kind = NodeKind::Number;
  Op op = Op::None;
  bool is_int = false;
  double number = 0;
  std::string_view text;  // name or string literal (points into the block's buffer)
  int a = -1;             // Unary/Binary: left child; Index/Call/RIndex: first entry in `args`
  int b = -1;             // Binary: right child; Index/Call/RIndex: argument count
};

// X=AC(..), X=IC(..); X=DAC(..), DIC, RAC, RIC: absolute/incremental in diameter/radius for this
// word only (PM-NC "Axis-specific diameter programming").
// A=DC(..), ACP(..), ACN(..): absolute on a modulo rotary axis, shortest way / positive /
// negative direction (PM-NC "Absolute dimensions for rotary axes").
enum class AxisMode : std::uint8_t { Default, AC, IC, DAC, DIC, RAC, RIC, DC, ACP, ACN };

enum class StmtKind : std::uint8_t {
  Word,      // address word: X10, X=R1, G1, M2=6, T="NAME", CR=5, DISC=50
  Assign,    // R1=5, VAR[1]=2, $TC_DP1[1,1]=120, $SC_NAME=1, SD42940=17
  Keyword,   // DEF, IF, ELSE, ..., GOTOF, TRANS, NORM, STOPRE, RET, ...
  CaseArm,   // CASE arm: `value GOTOF target` (expr = -1 for DEFAULT)
  Call,      // bare name: subprogram call (or L123)
  ProcCall,  // NAME(args) as a statement: MSG(..), CHANDATA(..), predefined procedures
};

// The jump statements (PM-JP "Program jumps"): which way the destination is searched.
enum class JumpKind : unsigned char {
  None,   // no jump
  Gotof,  // GOTOF: forward (towards the program end)
  Gotob,  // GOTOB: backward (towards the program start)
  Goto,   // GOTO: forward first, then backward; alarm 14080 if not found
  Gotoc,  // GOTOC: as GOTO, but no alarm if not found (the program continues)
};

struct Stmt {
  StmtKind kind = StmtKind::Word;
  std::string_view name;           // address, keyword, variable or program name
  int ext = -1;                    // address extension (M2=6 -> 2)
  int expr = -1;                   // value / right-hand side / condition / start value
  int expr2 = -1;                  // FOR: end value; PROC: attribute bits (ProcAttribute)
  int target = -1;                 // Assign and FOR: l-value node; jumps: target node
  JumpKind jump = JumpKind::None;  // a jump statement (also in a CaseArm or after IF)
  AxisMode mode = AxisMode::Default;
  bool has_equals = false;
  bool literal = false;  // Word with a plain number (X10): value in literal_value, expr = -1
  bool literal_int = false;
  double literal_value = 0;
  int column = 0;  // 1-based column of the statement
};

// Variable declaration from DEF.
enum class VarType : std::uint8_t { Int, Real, Bool, String, Char, Axis, Frame };
// The attributes of a DEF that ncoffset keeps: the limits LLI/ULI (PM-JP "Attributes").
struct DefAttributes {
  bool has_lower = false, has_upper = false;
  double lower = 0, upper = 0;
};
struct Decl {
  VarType type = VarType::Real;
  std::string_view name;
  int string_length = 0;  // STRING[n]
  int dims[2] = {0, 0};   // 0 = not an array
  int init = -1;          // node of a scalar initial value
  int init_first = -1;    // SET(...)/REP(...) list: first entry in `args`
  int init_count = 0;
  bool init_rep = false;  // REP(x): fill the array with x
  bool by_ref = false;    // PROC/EXTERN parameter with VAR (call by reference)
  int column = 0;
  bool global = false;  // DEF NCK / DEF CHAN: global user data (GUD)
  DefAttributes attributes;
};

// Attributes of a PROC statement (PM-JP "Subprogram technique"), bits of the statement's expr2.
enum ProcAttribute : int {
  kProcSave = 1,       // SAVE: modal G functions and frames restored at the return
  kProcSblof = 2,      // SBLOF: one single block
  kProcDisplof = 4,    // DISPLOF: the call block is displayed instead
  kProcActblocno = 8,  // ACTBLOCNO: with DISPLOF, alarms name the block inside
  kProcIcycof = 16,    // ICYCOF: technology cycles in one IPO cycle
  kProcPrepro = 32,    // PREPRO: prepared at power-on
};

struct Block {
  int line = 0;
  bool skip = false;  // "/" skippable block
  int skip_level = 0;
  bool has_number = false;  // N<no> or :<no>
  long long number = 0;
  std::string_view label;  // "LABEL:" (without the colon)
  // Every statement is an address word with a plain number (Parser::simpleWords took the
  // block): the interpreter collects them without looking at their kind.
  bool plain = false;
  std::vector<Stmt> stmts;
  std::vector<Node> nodes;
  std::vector<int> args;
  std::vector<Decl> decls;
  std::string buffer;  // upper-cased copy of the line that the views point into (it
                       // only grows: the line is its beginning, ended by a '\0')

  void clear() {
    line = 0;
    skip = false;
    skip_level = 0;
    has_number = false;
    number = 0;
    label = {};
    plain = false;
    stmts.clear();
    nodes.clear();
    args.clear();
    decls.clear();
  }
  const Node& node(int i) const { return nodes[static_cast<size_t>(i)]; }
  int arg(const Node& n, int k) const { return args[static_cast<size_t>(n.a + k)]; }
};

}  // namespace ncoffset::lang
