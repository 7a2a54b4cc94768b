// Frames in parametric programs (spec nc-parametric.md, NC-PARAM-FRAME-*, NC-PARAM-SYS-2): frame
// values, their components and the settable offsets a program writes, against the frame
// instructions written out by hand.
#include "parametric_support.hpp"
#include "support.hpp"

namespace cutcom::test {
namespace {

// covers: NC-PARAM-SYS-2
TEST(Parametric, ProgramWritesSettableOffsets) {
  // Written values take effect when an offset is selected next; the output stays in the system
  // of the first selected offset (G54 at X10): X5 there is 5, after G54 again with X12.5 it is 7.5,
  // and G55 at X100 puts X0 at 90.
  EXPECT_EQ(end_x("R1=5\n$P_UIFR[1]=CTRANS(X,R1*2,Y,0)\nG54 G1 X5 F100\n"), "5");
  EXPECT_EQ(end_x("$P_UIFR[1]=CTRANS(X,10)\nG54 G1 X5 F100\n$P_UIFR[1,X,TR]=12.5\nX5\n"), "5");
  EXPECT_EQ(end_x("$P_UIFR[1]=CTRANS(X,10)\nG54 G1 X5 F100\n$P_UIFR[1,X,TR]=12.5\nG54 X5\n"), "7.5");
  EXPECT_EQ(end_x("$P_UIFR[1]=CTRANS(X,10)\nG54 G1 X5 F100\n$P_UIFR[2]=CTRANS(X,100)\nG55 X0\n"), "90");
  EXPECT_EQ(error_line("G1 X1 F1\n$P_UIFR[1]=CTRANS(Q,1)\n", "an axis X, Y or Z is expected, not Q"), 2);
  EXPECT_EQ(error_line("G1 X1 F1\n$P_UIFR[1,Q,TR]=1\n", "'Q' is not a geometry axis"), 2);
  EXPECT_EQ(error_line("$P_UIFR[1]=CTRANS(X)\n", "CTRANS needs axis, value pairs"), 1);
}

// covers: NC-PARAM-FRAME-1 NC-FRAME-1 NC-FRAME-4
TEST(Parametric, FrameVariablesGiveTheFrameInstructionsPath) {
  const std::string contour = "G0 X0 Y0\nG1 G41 X10 Y0 F100\nY10\nG2 X0 Y10 CR=5\nG1 Y0\nG40 X-5 Y-5\n";
  const std::string head = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1.5\nG17 G90 T1 D1\n";
  const std::string parametric = head +
                                 "DEF FRAME PAL, SAVED\nDEF REAL AA=30\n"
                                 "PAL=CTRANS(X,10,Y,AA/6):CROT(Z,AA*3)\n"  // TRANS X10 Y5, AROT 90
                                 "$P_PFRAME=PAL\n" +
                                 contour + "$P_PFRAME=$P_PFRAME:CTRANS(X,100):CMIRROR(Y):CSCALE(X,2,Y,2)\n" + contour +
                                 "SAVED=$P_PFRAME\n$P_PFRAME=CTRANS()\nG0 X1 Y1\n"
                                 "$P_PFRAME=CTRANS(X,-50):SAVED\n" +
                                 contour + "$P_PFRAME=CRPL(0,45):CRPL(1,-45)\n" + contour + "M30\n";
  const std::string plain = head + "TRANS X10 Y5\nAROT RPL=90\n" + contour + "ATRANS X100\nAMIRROR Y0\nASCALE X2 Y2\n" +
                            contour +
                            "TRANS\nG0 X1 Y1\nTRANS X-50\nATRANS X10 Y5\nAROT RPL=90\nATRANS X100\n"
                            "AMIRROR Y0\nASCALE X2 Y2\n" +
                            contour + "TRANS\n" + contour + "M30\n";
  Runs p = run_both(parametric), q = run_both(plain);
  ASSERT_TRUE(p.fast_ok && p.ref_ok && q.fast_ok && q.ref_ok);
  EXPECT_GT(q.fast.path.size(), 20u);
  expect_same_path(p.fast, q.fast);
  expect_same_path(p.ref, q.ref);
  EXPECT_EQ(error_line("DEF FRAME FF\nFF=5\n", "FRAME variable is assigned a value that is not a frame"), 2);
  EXPECT_EQ(error_line("DEF REAL RR\nRR=CTRANS(X,1)\n", "a frame is assigned to a variable"), 2);
  EXPECT_EQ(error_line("G1 X=CTRANS(X,1) F100\n", "not a frame"), 1);
  EXPECT_EQ(error_line("$P_PFRAME=CTRANS(Q,1)\n", "an axis X, Y or Z is expected, not Q"), 1);
  EXPECT_EQ(error_line("$P_PFRAME=CTRANS(X,1):5\n", "a frame is needed after it"), 1);
  EXPECT_EQ(error_line("$P_PFRAME=CTRANS(X,1) G1 X5\n", "block of its own"), 1);
  EXPECT_EQ(error_line("$P_PFRAME=CROT(X,30)\n", "tilts the working plane"), 1);
  EXPECT_EQ(error_line("G1 G41 X1 Y1 F100 T1 D1\n$P_PFRAME=CTRANS(X,1)\n", "frame change"), 2);
}

// covers: NC-PARAM-FRAME-2 NC-PARAM-SYS-2
TEST(Parametric, FrameComponentsAndSettableFramesAsValues) {
  // Components written one by one give the frame the frame instructions give; read back, they
  // are what was written (the shift in the program's unit, RT about the applicate, SC, MI).
  const std::string contour = "G0 X0 Y0\nG1 G41 X10 Y0 F100\nY10\nG2 X0 Y10 CR=6\nG1 Y0\nG40 X-5 Y-5\n";
  const std::string head = "$TC_DP1[1,1]=120\n$TC_DP6[1,1]=1.5\nG17 G90 T1 D1\n";
  const std::string parametric = head +
                                 "$P_PFRAME[X,TR]=10\n$P_PFRAME[Y,TR]=$P_PFRAME[X,TR]/2\n$P_PFRAME[Z,RT]=30\n"
                                 "$P_PFRAME[Y,MI]=1\n$P_PFRAME[X,SC]=2\n$P_PFRAME[Y,SC]=2\n" +
                                 contour + "$P_PFRAME[Y,MI]=0\n$P_PFRAME[Z,RT]=$P_PFRAME[Y,SC]*10+$P_PFRAME[Y,MI]\n" +
                                 contour + "M30\n";
  const std::string plain = head + "TRANS X10 Y5\nAROT RPL=30\nASCALE X2 Y-2\n" + contour +
                            "TRANS X10 Y5\nAROT RPL=20\nASCALE X2 Y2\n" + contour + "M30\n";
  Runs p = run_both(parametric), q = run_both(plain);
  ASSERT_TRUE(p.fast_ok && p.ref_ok && q.fast_ok && q.ref_ok);
  EXPECT_TRUE(q.fast.alarms.empty());
  EXPECT_GT(q.fast.path.size(), 10u);
  expect_same_path(p.fast, q.fast);
  expect_same_path(p.ref, q.ref);
  EXPECT_EQ(end_x("G70\n$P_PFRAME[X,TR]=1\nR1=$P_PFRAME[X,TR]*100+$P_PFRAME[X,FI]\nG71 G1 X=R1 F100\n"), "125.4");
  // A settable offset read whole is a frame, by components its values; $P_IFRAME and
  // $P_UIFRNUM are the one in force. A frame of translations is written to an offset whole.
  EXPECT_EQ(end_x("$P_UIFR[1]=CTRANS(X,10,Y,5)\n$P_UIFR[2]=$P_UIFR[1]:CTRANS(X,1)\n"
                  "G55 G1 X=$P_UIFR[2,X,TR]+$P_UIFR[2,Y,SC] F100\n"),
            "12");
  EXPECT_EQ(end_x("$P_UIFR[3,X,TR]=7\nG56\nR1=$P_IFRAME[X,TR]*10+$P_UIFRNUM\n$P_PFRAME=$P_IFRAME\n"
                  "G1 X=R1 F100\n"),
            "80");  // 73, shifted by the programmable frame that copies G56's 7
  EXPECT_EQ(error_line("$P_UIFR[1]=CROT(Z,30)\n", "a settable offset holds translations only"), 1);
  EXPECT_EQ(error_line("$P_UIFR[1]=5\n", "not a frame"), 1);
  EXPECT_EQ(error_line("$P_PFRAME[Q,TR]=5\n", "an axis X, Y or Z is expected"), 1);
  EXPECT_EQ(error_line("$P_PFRAME[X,QQ]=5\n", "'QQ' is not a frame component"), 1);
  EXPECT_EQ(error_line("$P_PFRAME[X,SC]=0\n", "a scale factor must be positive"), 1);
  EXPECT_EQ(error_line("$P_PFRAME[X,MI]=2\n", "a mirror component is 0 or 1"), 1);
  EXPECT_EQ(error_line("$P_PFRAME[X,RT]=30\n", "tilts the working plane"), 1);
  EXPECT_EQ(error_line("$P_PFRAME[X,TR]=5 G1 X1\n", "block of its own"), 1);
  EXPECT_EQ(error_line("G1 G41 X1 Y1 F100 T1 D1\n$P_PFRAME[X,TR]=1\n", "frame change"), 2);
  EXPECT_EQ(error_line("R1=$P_PFRAME[X]\n", "read as a frame or by a component"), 1);
  EXPECT_EQ(error_line("R1=$P_ACTFRAME[X,TR]\n", "frame variable $P_ACTFRAME is not simulated"), 1);
}

// covers: NC-PARAM-SYS-5 NC-OFFSET-1
TEST(Parametric, ProgramWritesTheSettableFrameInForce) {
  const std::string offsets = "$P_UIFR[1]=CTRANS(X,10,Y,20)\n$P_UIFR[2]=CTRANS(X,110,Y,20)\nG54 G0 X0 Y0\n";
  // $P_IFRAME=$P_UIFR[n] activates offset n without its G function: X0 is at 110, 100 from G54's 10.
  EXPECT_EQ(end_x(offsets + "R10=2\n$P_IFRAME=$P_UIFR[R10]\nG1 X0 F100\n"), "100");
  // A component of the frame in force, and a frame of its own; G54 selects its offset again.
  EXPECT_EQ(end_x(offsets + "$P_IFRAME[X,TR]=15\nG1 X0 F100\n"), "5");
  EXPECT_EQ(end_x(offsets + "$P_IFRAME=CTRANS(X,5)\nG1 X1 F100\n"), "-4");
  EXPECT_EQ(end_x(offsets + "$P_IFRAME=CTRANS(X,5)\nG1 X1 F100\nG54 X1\n"), "1");
  // It comes from the next block on; group 8 still names G54.
  EXPECT_EQ(end_x(offsets + "$P_IFRAME=$P_UIFR[2]\nG1 X=$P_UIFRNUM*10+$P_GG[8] F100\n"), "112");
  // First of all: the output is in its system.
  EXPECT_EQ(end_x("$P_IFRAME=CTRANS(X,7)\nG1 X1 F100\n"), "1");
  EXPECT_EQ(error_line("$P_IFRAME=CROT(Z,30)\n", "a settable offset holds translations only"), 1);
  EXPECT_EQ(error_line("$P_IFRAME=3\n", "$P_IFRAME is assigned a value that is not a frame"), 1);
  EXPECT_EQ(error_line("$P_IFRAME[Q,TR]=3\n", "$P_IFRAME: "), 1);
  EXPECT_EQ(error_line("$TC_DP1[1,1]=120\n$TC_DP6[1,1]=2\nT1 D1 G1 G41 X1 Y1 F100\n$P_IFRAME=CTRANS(X,1)\n",
                       "frame change with tool radius compensation"),
            4);
}

}  // namespace
}  // namespace cutcom::test
