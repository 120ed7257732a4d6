// The channel interpreter: executes blocks one at a time (streaming), keeps the modal state of
// the G groups, variables, setting/machine data and frames, and hands each motion to the
// placement stage. Program flow per PM-JP "Program flow control" and PM-NC "Subprograms".
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/stage.hpp"
#include "interp/channel_axes.hpp"
#include "interp/contour_state.hpp"
#include "interp/frame_state.hpp"
#include "interp/loop_watch.hpp"
#include "interp/machine_data.hpp"
#include "interp/modal_state.hpp"
#include "interp/motion_builder.hpp"
#include "interp/program_flow.hpp"
#include "interp/subprogram_call.hpp"
#include "interp/toolholder_words.hpp"
#include "interp/variable_store.hpp"
#include "interp/variables.hpp"
#include "lang/block.hpp"
#include "lang/evaluator.hpp"
#include "lang/macro_table.hpp"
#include "lang/parser.hpp"
#include "lang/program_index.hpp"
#include "lang/source_file.hpp"
#include "ncoffset/channel.hpp"
#include "ncoffset/frame.hpp"
#include "tool/tool_selection.hpp"

namespace ncoffset::out {
struct OffsetReadout;
}

namespace ncoffset::interp {

class Interpreter final : public lang::Environment {
 public:
  // `first`: the stage that takes the motion blocks (smooth approach); `sink`: MSG texts.
  Interpreter(const RunOptions& options, PathSink& sink, core::Stage& first);
  ~Interpreter() override;

  // Runs a file as an init file or as the main program. Throws AlarmError; `alarmLoc()` then
  // tells where.
  void run(LoadedProgram& program, bool init_file);
  LoadedProgram& load(std::shared_ptr<lang::SourceFile> source, bool init_file = false);
  SourceLoc alarmLoc(const AlarmError& e) const;
  // The text of the line alarmLoc() names ("" where it is not known).
  std::string alarmSourceLine(const AlarmError& e) const;
  const std::string& fileName(int id) const { return flow_.fileName(id); }
  // What the HTML report shows besides the path: the files of the run with their text, the
  // axis dynamics ($MA_...) and the offset memory.
  size_t fileCount() const { return flow_.fileCount(); }
  std::string_view fileText(int id) const { return flow_.text(id); }
  const MachineData& machineData() const { return data_; }
  const tool::ToolStore& toolStore() const { return tools_.store(); }
  long long blocksExecuted() const { return executed_; }
  // The transverse axis of MD20100 (0 X, 1 Y, 2 Z; -1 none).
  int transverseAxis() const;
  void writeVariablesJson(std::ostream& out) const;
  // How many motions went to the first stage (events are ordered against them).
  long long motionsSent() const { return motion_.motionsSent(); }
  void setSearchDir(std::filesystem::path dir) { flow_.setSearchDir(std::move(dir)); }
  void setSearchPath(std::vector<std::filesystem::path> path) {
    flow_.setSearchPath(std::move(path));
  }

  // lang::Environment
  bool read(std::string_view name, std::span<const lang::Value> indices, bool indexed,
            lang::Value& out) override;
  lang::Value readR(double number) override;
  lang::Value call(std::string_view name, std::span<const lang::Value> args) override;
  lang::Value chain(const lang::Value& a, const lang::Value& b) override;

 private:
  // --- program flow (interpreter.cpp) ---
  void executeBlock();
  void executeControl(const lang::Stmt& st, size_t index, bool& jumped);
  // --- events for simulations (events.cpp; only when the sink wants them) ---
  void mFunctionEvent(double m, int ext);
  void spindleEvent(double s, int ext);
  void toolEvent();
  void blockEvents(double feed_before);
  void stopEvent();
  // control_statements.cpp
  void ifStatement(const lang::Stmt& st, size_t index, bool& jumped);
  bool loopStatement(const lang::Stmt& st, bool& jumped);
  void caseStatement(const lang::Stmt& st, size_t index, bool& jumped);
  void jump(const lang::Stmt& st, bool quiet);
  void jumpTo(lang::JumpKind kind, int target_node, bool quiet);
  // The endless-loop proof (loop_guard.cpp): statements that may change the next pass, and a
  // jump that went back from the line at offset `from` (alarm 99007 on the second clean pass).
  void watchKeyword(const lang::Stmt& st);
  void watchProcCall(const lang::Stmt& st);
  void watchWord(const lang::Stmt& st);
  void blockBudgetReached();
  void backEdge(size_t from);
  void callSubprogram(std::string_view name, long long repeat);
  // Finds a subprogram file beside the main program (nullptr if there is none).
  bool programExists(std::string_view name);
  // Runs `f`, which may load a program: an alarm of the new program's index belongs to it.
  template <typename F>
  decltype(auto) loading(F&& f);
  void returnFromSubprogram();
  void endProgram();
  // section_repeat.cpp: REPEAT/REPEATB with labels; M17/RET/M2/M30 (`program_end`) by level.
  void repeatSection(const lang::Stmt& st, bool& jumped);
  void endWord(bool program_end);

  // --- subprograms with parameters, MCALL, SAVE (subprogram_call.cpp, call_arguments.cpp) ---
  // PROC, EXTERN, MCALL, CALL, PCALL; false for any other keyword.
  bool callStatement(const lang::Stmt& st);
  void procStatement(const lang::Stmt& st);
  void modalCallStatement(const lang::Stmt& st);
  void indirectCall(const lang::Stmt& st);
  // NAME(args) names a subprogram (not a predefined procedure).
  bool isSubprogramName(std::string_view name);
  bool readCallVariable(std::string_view name, std::span<const lang::Value> idx, lang::Value& out);
  // The block calls `name` at its end with the arguments of the Call node `args_node`.
  void collectCall(std::string_view name, int args_node);
  std::vector<CallArg> actualArguments(int args_node, bool modal);
  void enterSubprogram(std::string_view name, long long repeat, std::vector<CallArg> args,
                       bool modal);
  void leaveSubprogram();
  const ProcSignature& signatureOf(const LoadedProgram& prog);
  void bindParameters(CallFrame& frame);
  void bindParameter(const FormalParameter& p, const CallArg& a, size_t position, CallFrame& frame);
  void restoreSaved(const CallFrame& frame);
  // After a block that moved a geometry axis: the active MCALL subprogram (PM-JP "MCALL").
  void modalCallAfter();
  void resetCalls();
  // CALL [name] BLOCK start TO end (subprogram_call.cpp).
  void callSection(const lang::Stmt& st);
  bool sectionJump(int target_node);
  void endSection();
  const lang::ControlLink& link() const { return flow_.link(line_pos_.offset); }
  void define(const lang::Decl& d);
  void assign(const lang::Stmt& st);
  void store(const lang::Node& target, const lang::Value& v);

  void startRun(LoadedProgram& program, bool init_file);  // run()'s state (plain_line.cpp)

  // --- words, modal state, motion (block_executor.cpp) ---
  void collectWord(const lang::Stmt& st);
  // X, Y, Z, G0..G3, G40..G42, F, CR= of a plain block, inline; the plain block and the plain
  // line (plain_line.cpp, docs/performance.md sections 25, 27, 30, 34).
  bool plainWord(std::string_view name, double value, bool is_int, Motion& motion,
                 core::TrcMode& trc);
  bool plainAxis(int i, double value);
  bool plainFeed(double value);           // F: false beyond 0..1e9 (collectWord's alarm)
  bool plainRadius(double value);         // CR=: false a second time or with a variable CR
  bool plainCentre(int i, double value);  // I, J, K (i 0..2): false a second time
  bool plainG(double value, bool is_int, Motion& motion, core::TrcMode& trc);
  bool plainGCode(unsigned long long g, Motion& motion, core::TrcMode& trc);
  void executePlainBlock(const lang::Block& b);
  // True: the line's words are collected. `ended`: the character after `text` may be read.
  bool plainLine(std::string_view text, bool ended);
  bool scanPlainLine(std::string_view text, bool ended);
  template <class AtEnd>
  const char* plainWords(const char* base, AtEnd at_end, Motion& motion, core::TrcMode& trc);
  void takePlainLine(Motion motion, core::TrcMode trc);
  // The next line read and collected in one pass if it is plain (plain_line.cpp).
  enum class InPlace { Taken, No, Refused };
  InPlace lineInPlace(ProgramLevel& lvl, size_t max_len);
  bool inPlaceAllowed(const ProgramLevel& lvl) const;
  void countLine(ProgramLevel& lvl);                   // run()'s bookkeeping of a line read
  [[gnu::noinline]] void lineStop(ProgramLevel& lvl);  // countLine's rare tests
  bool plainLineWord(const char*& p, Motion& motion, core::TrcMode& trc);
  void finishPlainLine() {  // inline: once a block, from run()
    words_plain_ = false;   // until the block is through without an alarm (executeBlock)
    finishPlainBlock(plain_column_);
    words_plain_ = true;
  }
  double wordValue(const lang::Stmt& st);
  void letterWord(const lang::Stmt& st);
  void programWord(char c, const lang::Stmt& st);
  void extendedWord(const lang::Stmt& st);
  void sarWord(const lang::Stmt& st);
  void namedWord(const lang::Stmt& st);
  void gCode(int code);
  // gCode() by G groups: true when the group knows `g`.
  bool gMotionPlaneFrame(int g);
  bool gCompensation(int g);
  bool gUnitsAndFeed(int g);
  void gNotModelled(int g);
  void setSar(core::SarKind kind);
  void finishBlock();
  void finishPlainBlock(int column);  // finishBlock for plainWord's words (plain_line.cpp)
  bool blockFrames();  // the frame words of the block; true when they took its axis values
  void doFrameCommand();
  double toMm(double v) const;

  // STRG[i] of a STRING variable (string_chars.cpp); false for another type.
  bool readStringChar(const UserVariable& v, std::span<const lang::Value> idx,
                      std::string_view name, lang::Value& out);
  bool writeStringChar(UserVariable& v, std::span<const lang::Value> idx, std::string_view name,
                       const lang::Value& x);
  // --- additional axes (axis_words.cpp, docs/language.md "Axes") ---
  bool axisWord(const lang::Stmt& st);
  size_t settableIndex() const;
  bool axesBlock(bool consumed, bool geometry_motion);
  void announceAxes();
  int anyAxis(const lang::Value& v, std::string_view what) const;
  bool axisDataRead(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                    lang::Value& out);
  bool axisDataWrite(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                     const lang::Value& v);
  bool axisFrameWrite(std::string_view name, std::span<const lang::Value> idx,
                      const lang::Value& v);

  // --- turning (turning.cpp, turning_data.cpp) ---
  bool diameterWord(std::string_view w);
  bool turningWord(const lang::Stmt& st);
  bool diameterAxisCall(std::string_view name, std::span<const lang::Value> args);
  bool diameterPermitted(int axis) const;
  void setDiameterMode(DiamMode m, std::string_view word);
  // I, J, K in a block without G2/G3: the lead of a thread block (threads.cpp), else 14045.
  void threadLeadWords();
  // G33, G34, G35, G331, G332 (group 1): the modal motion; false for another G number.
  bool threadMotionWord(int g);
  void updateDiameter();
  void resetDiameterAxes();
  double readPosition(double radius_value, int ax) const;
  void setFeedType(FeedType t);
  void applyResetValue(int index, int value);
  int resetIndex(std::span<const lang::Value> idx, bool indexed) const;
  bool turningDataRead(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                       lang::Value& out);
  bool turningDataWrite(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                        const lang::Value& v);

  // --- contour definitions, CIP/CT, polar coordinates (contour_definition.cpp) ---
  bool contourWord(const lang::Stmt& st);
  void circleFormWord(CircleForm form);
  void poleWord(int g);
  bool contourBlock(bool axes_consumed, bool& builds, bool& moved);
  void definePole();
  void polarTarget();
  bool angleLine(bool builds);
  void buildPendingLine(const Vec3& end);
  void circleForm();
  void cipCircle(PlaneAxes pa, const Vec3& from, const Vec3& to);
  void ctCircle(PlaneAxes pa, const Vec3& from, const Vec3& to);
  CornerRequest cornerRequest() const;

  // --- tool data and selection (tool_selection.cpp) ---
  void executeToolWords();
  // The orientable toolholder (toolholder_words.cpp, docs/toolholders.md).
  void toolholderNumber(double m);  // TCARR=m
  bool toolholderNamedWord(std::string_view w);
  void executeCarrierWords();
  std::array<double, 2> carrierAxisAngles(int m) const;
  Mat3 toolFrameRotation(ToolFrame variant) const;
  bool readCarrier(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                   lang::Value& out);
  bool writeCarrier(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                    const lang::Value& v);
  lang::Value callLentoax(std::span<const lang::Value> args);
  // The caller's array for an array parameter of `fn` (alarm 14020 for anything else).
  std::span<lang::Value> arrayArgument(std::string_view fn, const lang::Value& ref, bool integer,
                                       int rows, int cols, const char* what);

  // --- D numbers, tool environments (tool_functions.cpp) ---
  // CHKDNO, GETDNO, SETDNO, DZERO, GETACTTD, GETACTT, TOOLENV, DELTOOLENV, GETTENV, GETTCOR,
  // SETTCOR.
  bool toolFunction(std::string_view name, std::span<const lang::Value> args, lang::Value& out);
  void configureDNumbers();  // MD18102, MD18105, MD18106 into the tool selection
  // Writes `v` to the k-th argument of the call of `fn` in this block (a VAR parameter).
  void storeCallArgument(std::string_view fn, size_t k, const lang::Value& v, bool required);
  lang::Value toolEnvironmentCall(std::string_view name, std::span<const lang::Value> args);
  lang::Value callGettcor(std::span<const lang::Value> args);
  lang::Value callSettcor(std::span<const lang::Value> args);
  // The environment `stat` names (empty: the current state): status 0, -1 (MD18116 = 0), -2.
  int toolEnvironmentFor(const std::string& stat, tool::ToolEnvironment& env);

  // --- system variables and frame functions (system_variables.cpp) ---
  bool readSystem(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                  lang::Value& out);
  void writeSystem(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                   const lang::Value& v);
  // X, Y, Z as 0, 1, 2 (99010 for another axis, 12150 for no axis name).
  int axisIndexOf(const lang::Value& v) const;
  Frame* frameByName(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                     bool& whole);

  // --- predefined names without code of their own (predefined_calls.cpp, docs/names.md) ---
  // A bare name (SOFT, COMPCAD, CUT2DF): true when accepted, alarm 99010 for a (c) name, false
  // when the table does not know it (a subprogram call).
  bool predefinedWord(std::string_view name);
  // NAME(args) (WAITM(..), SETAL(..), ISVAR(..), CYCLE81(..)): false when unknown.
  bool predefinedCall(std::string_view name, std::span<const lang::Value> args, lang::Value& out);
  // DL=, TOFFL=, TOFFL[n]=, TOFF[ax]=, TOFFR= and $P_TOFFL/$P_TOFF/$P_TOFFR
  // (programmable_offsets.cpp): false for other names.
  bool offsetWordWrite(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                       const lang::Value& v);
  bool offsetWordRead(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                      lang::Value& out);
  tool::SelectionContext selectionContext() const;
  out::OffsetReadout offsetReadout() const;
  void syncSumOffsetLimits();  // MD18110, MD18112 -> the tool selection
  // NAME=value, NAME[i]=value (ADIS=0.5, ACC[X]=80, DL=0): false when unknown.
  bool predefinedAssign(std::string_view name, const lang::Value& v);
  // Reading a (c) name: alarm 99010 (false when the table does not know it).
  bool predefinedRead(std::string_view name);
  lang::Value isVar(std::span<const lang::Value> args);
  void fileErrorZero(std::string_view name);
  // --- position and state reads (state_variables.cpp): $AA_IW, $AA_IM, $P_GG, $P_F ---
  bool readState(std::string_view name, std::span<const lang::Value> idx, bool indexed,
                 lang::Value& out);
  double* partCounter(std::string_view name);
  Vec3 mainRunStop();
  // ARRAY[i]=SET(..) / ARRAY[i]=REP(..) (array_assign.cpp).
  bool arrayListAssign(const lang::Stmt& st);
  int gGroupIndex(int group) const;

  RunOptions options_;
  core::Stage& first_;
  double feed_before_ = 0;             // the modal feed before the current block
  Motion motion_before_ = Motion::G0;  // the modal G0..G3 before the current block
  PathSink& sink_;
  lang::Evaluator eval_;
  MachineData data_;
  VariableStore vars_;  // after data_: MD28050 sizes the R parameters
  ModalState modal_;
  BlockWords words_;
  // The last block's words were all collected by plainWord and nothing after it wrote to
  // words_ (executeBlock): the next block clears them with BlockWords::clearPlain.
  bool words_plain_ = false;
  ContourWords contour_words_;  // valid when words_.contour
  ContourState contour_;
  bool contour_active_ = false;  // RNDM, CIP/CT or a pending ANG block: every block looks
  std::string call_name_;        // storage for an L<number> program name

  ProgramFlow flow_;
  lang::MacroTable macros_;             // DEFINE .. AS (PM-JP "Macro technique")
  std::string expanded_;                // the current block with its macros expanded
  std::vector<CallFrame> call_frames_;  // one per subprogram level (flow_.depth() - 1)
  std::unordered_map<int, ProcSignature> signatures_;          // by file id
  std::map<std::string, ProcSignature, std::less<>> externs_;  // EXTERN declarations
  ModalCall mcall_;
  int modal_depth_ = 0;  // levels of an MCALL subprogram (and what it calls) now running
  size_t section_end_ = static_cast<size_t>(-1);  // the top level's CallFrame::section_end
  // Kept here, not in BlockWords, so that a block without a call pays nothing for them:
  int call_args_ = -1;      // NAME(args) of this block: the Call node of the arguments
  bool mcall_set_ = false;  // MCALL NAME in this block: the block itself does not call
  lang::Block scan_block_;  // a subprogram's first block, parsed for its PROC header

  lang::Block block_;
  std::string line_copy_;                  // plainLine's copy of the line, ended by a '\0'
  int plain_column_ = 0;                   // of the first word of the plain line
  std::array<const char*, 32> refused_{};  // lines plainLine refused, by their text's address
  bool in_place_ = false;   // inPlaceAllowed held when asked, and only plain lines ran since
  lang::TextPos line_pos_;  // start of the executing line
  int line_ = 0;
  int column_ = 0;              // of the executing statement (0: the line as a whole)
  std::string_view line_text_;  // the executing line (a view into its loaded file)
  int file_ = 0;
  long long executed_ = 0;
  long long run_start_ = 0;       // executed_ when the run began
  long long block_budget_ = 0;    // executed_ beyond which blockBudgetReached() decides (99002)
  long long line_stop_ = 0;       // executed_ from which countLine takes lineStop
  long long without_motion_ = 0;  // blocks executed since the last motion
  LoopWatch loop_;                // ends a loop that provably never ends (99007)
  size_t for_continue_ = static_cast<size_t>(-1);
  bool ended_ = false;
  bool init_file_ = false;
  bool events_ = false;      // the sink wants events (PathSink::wantsEvents)
  bool stop_after_ = false;  // M0/M1 in this block: the event follows its motion
  int stop_m_ = 0;
  bool has_s_ = false;            // the block's S word (events only): speed, or G4 revolutions
  core::BlockFrame event_frame_;  // the frame of the last FrameEvent (events only)
  double dwell_s_ = 0;
  int dwell_s_ext_ = 0;

  FrameState frames_;
  ChannelAxes axes_;                                   // the axes beyond X, Y, Z (axis_words.cpp)
  int md_max_disc_ = 0;                                // MD20220, looked up once
  int md_transverse_ = 0, md_base_function_mask_ = 0;  // MD20100, MD30460
  // MD20150 by G group - 1 (the modelled groups: turning_data.cpp).
  std::array<int, 60> reset_values_{};
  // $AC_TOTAL_PARTS, $AC_REQUIRED_PARTS, $AC_ACTUAL_PARTS, $AC_SPECIAL_PARTS (state_variables.cpp)
  double part_counters_[4] = {0, 0, 0, 0};

  // Tool offsets (W1): the offset memory, the active tool and edge, and what the selection
  // snapshotted (data, setting data and mirroring act from the next edge selection).
  tool::ToolSelection tools_;
  tool::ToolCarriers carriers_{0};
  CarrierState carrier_;
  int md_carriers_ = 0, sd_carrier_fine_ = 0;  // MD18088, SD42974
  MotionBuilder motion_;                       // after first_, data_, frames_, tools_
  int md_change_mode_ = 0, md_change_m_ = 0, md_default_edge_ = 0;
  int sd_mirror_length_ = 0, sd_mirror_wear_ = 0, sd_cutpos_ = 0, sd_wear_sign_ = 0,
      sd_length_const_ = 0, sd_length_type_ = 0;
};

}  // namespace ncoffset::interp
