//! Catalogue chapter: math (manual §1.15): arithmetic, trigonometry, geometry, digit strings, bits, matrices.

use super::entry::*;

pub(crate) const ENTRIES: &[Entry] = &[
    // --- Simple calculations on numeric data -------------------------------------------
    routine(r#"PROC Clear(INOUT num Name | INOUT dnum Dname)"#, "Sets a num or dnum variable or persistent to zero."),
    routine(
        r#"PROC Add(INOUT num Name | INOUT dnum Dname, num AddValue | dnum AddDvalue)"#,
        "Adds a value to a num or dnum variable or persistent.",
    ),
    routine(
        r#"PROC Incr(INOUT num Name | INOUT dnum Dname)"#,
        "Increases a num or dnum variable or persistent by one.",
    ),
    routine(
        r#"PROC Decr(INOUT num Name | INOUT dnum Dname)"#,
        "Decreases a num or dnum variable or persistent by one.",
    ),
    // uncertain: listed in the RW 6.15.04 overview (§1.15) only; no public signature found.
    routine(r#"FUNC num Rand()"#, "Returns a pseudo-random number."),
    // --- Arithmetic functions ------------------------------------------------------------
    routine(r#"FUNC num Abs(num Value)"#, "Returns the absolute value of a num."),
    routine(r#"FUNC dnum AbsDnum(dnum Value)"#, "Returns the absolute value of a dnum."),
    routine(
        r#"FUNC num Round(num Val \num Dec)"#,
        "Rounds a num to Dec decimals (to an integer when Dec is left out).",
    ),
    routine(
        r#"FUNC dnum RoundDnum(dnum Val \num Dec)"#,
        "Rounds a dnum to Dec decimals (to an integer when Dec is left out).",
    ),
    routine(
        r#"FUNC num Trunc(num Val \num Dec)"#,
        "Cuts a num after Dec decimals without rounding (integer part by default).",
    ),
    routine(
        r#"FUNC dnum TruncDnum(dnum Val \num Dec)"#,
        "Cuts a dnum after Dec decimals without rounding (integer part by default).",
    ),
    routine(r#"FUNC num Max(num A, num B)"#, "Returns the larger of two numbers."),
    routine(r#"FUNC num Min(num A, num B)"#, "Returns the smaller of two numbers."),
    routine(r#"FUNC num Sqrt(num Value)"#, "Returns the square root of a non-negative num."),
    routine(r#"FUNC dnum SqrtDnum(dnum Value)"#, "Returns the square root of a non-negative dnum."),
    routine(r#"FUNC num Exp(num Exponent)"#, "Returns e raised to the given exponent."),
    routine(r#"FUNC num Pow(num Base, num Exponent)"#, "Returns Base raised to Exponent."),
    routine(r#"FUNC dnum PowDnum(dnum Base, num Exponent)"#, "Returns a dnum Base raised to Exponent."),
    routine(r#"FUNC num ACos(num Value)"#, "Arc cosine in degrees (0 to 180) of a value in [-1, 1]."),
    routine(r#"FUNC dnum ACosDnum(dnum Value)"#, "Arc cosine in degrees of a dnum value in [-1, 1]."),
    routine(r#"FUNC num ASin(num Value)"#, "Arc sine in degrees (-90 to 90) of a value in [-1, 1]."),
    routine(r#"FUNC dnum ASinDnum(dnum Value)"#, "Arc sine in degrees of a dnum value in [-1, 1]."),
    routine(r#"FUNC num ATan(num Value)"#, "Arc tangent in degrees, in the range -90 to 90."),
    routine(r#"FUNC dnum ATanDnum(dnum Value)"#, "Arc tangent in degrees of a dnum, in the range -90 to 90."),
    routine(r#"FUNC num ATan2(num Y, num X)"#, "Arc tangent of Y/X in degrees, using both signs (range -180 to 180)."),
    routine(
        r#"FUNC dnum ATan2Dnum(dnum Y, dnum X)"#,
        "Arc tangent of Y/X in degrees for dnum values (range -180 to 180).",
    ),
    routine(r#"FUNC num Cos(num Angle)"#, "Cosine of an angle given in degrees."),
    routine(r#"FUNC dnum CosDnum(dnum Angle)"#, "Cosine of a dnum angle given in degrees."),
    routine(r#"FUNC num Sin(num Angle)"#, "Sine of an angle given in degrees."),
    routine(r#"FUNC dnum SinDnum(dnum Angle)"#, "Sine of a dnum angle given in degrees."),
    routine(r#"FUNC num Tan(num Angle)"#, "Tangent of an angle given in degrees."),
    routine(r#"FUNC dnum TanDnum(dnum Angle)"#, "Tangent of a dnum angle given in degrees."),
    // --- Orientation, pose and vector functions -----------------------------------------
    routine(
        r#"FUNC num EulerZYX(\switch X | switch Y | switch Z, orient Rotation)"#,
        "Returns one ZYX Euler angle (degrees) of a quaternion orientation.",
    ),
    routine(
        r#"FUNC orient OrientZYX(num ZAngle, num YAngle, num XAngle)"#,
        "Builds a quaternion orientation from ZYX Euler angles in degrees.",
    ),
    routine(r#"FUNC pose PoseInv(pose Pose)"#, "Returns the inverse of a frame transformation."),
    routine(
        r#"FUNC pose PoseMult(pose Pose1, pose Pose2)"#,
        "Returns the product Pose1 * Pose2 of two frame transformations.",
    ),
    routine(r#"FUNC pos PoseVect(pose Pose, pos Pos)"#, "Transforms a position with a pose."),
    routine(r#"FUNC num VectMagn(pos Vector)"#, "Returns the length of a pos vector."),
    routine(r#"FUNC num DotProd(pos Vector1, pos Vector2)"#, "Returns the scalar (dot) product of two pos vectors."),
    routine(
        r#"FUNC pos CrossProd(pos Vector1, pos Vector2)"#,
        "Returns the vector (cross) product of two pos vectors.",
    ),
    routine(r#"FUNC orient NOrient(orient Rotation)"#, "Normalises a quaternion so that it has unit length."),
    // --- Digit-string arithmetic ----------------------------------------------------------
    routine(
        r#"FUNC bool StrDigCmp(stringdig StrDig1, opnum Relation, stringdig StrDig2)"#,
        "Compares two digit strings as non-negative integers.",
    ),
    routine(
        r#"FUNC stringdig StrDigCalc(stringdig StrDig1, opcalc Operation, stringdig StrDig2)"#,
        "Does integer arithmetic on two digit strings and returns a digit string.",
    ),
    // --- Bit functions --------------------------------------------------------------------
    routine(
        r#"PROC BitSet(INOUT byte BitData | INOUT dnum DnumData, num BitPos)"#,
        "Sets one bit (1-8 in a byte, 1-52 in a dnum) to 1.",
    ),
    routine(
        r#"PROC BitClear(INOUT byte BitData | INOUT dnum DnumData, num BitPos)"#,
        "Clears one bit (1-8 in a byte, 1-52 in a dnum) to 0.",
    ),
    routine(r#"FUNC bool BitCheck(byte BitData, num BitPos)"#, "Tells whether bit BitPos (1-8) of a byte is 1."),
    routine(
        r#"FUNC bool BitCheckDnum(dnum Value, num BitPos)"#,
        "Tells whether bit BitPos (1-52) of an integer dnum is 1.",
    ),
    routine(r#"FUNC byte BitAnd(byte BitData1, byte BitData2)"#, "Bitwise AND of two bytes."),
    routine(r#"FUNC dnum BitAndDnum(dnum Value1, dnum Value2)"#, "Bitwise AND of two integer dnum values."),
    routine(r#"FUNC byte BitOr(byte BitData1, byte BitData2)"#, "Bitwise inclusive OR of two bytes."),
    routine(r#"FUNC dnum BitOrDnum(dnum Value1, dnum Value2)"#, "Bitwise inclusive OR of two integer dnum values."),
    routine(r#"FUNC byte BitXOr(byte BitData1, byte BitData2)"#, "Bitwise exclusive OR of two bytes."),
    routine(r#"FUNC dnum BitXOrDnum(dnum Value1, dnum Value2)"#, "Bitwise exclusive OR of two integer dnum values."),
    routine(r#"FUNC byte BitNeg(byte BitData)"#, "One's complement of a byte."),
    routine(
        r#"FUNC dnum BitNegDnum(dnum Value \num Size)"#,
        "One's complement of an integer dnum, over Size bits when given.",
    ),
    routine(
        r#"FUNC byte BitLSh(byte BitData, num ShiftSteps)"#,
        "Shifts a byte left by 1-8 steps; bits pushed out are lost.",
    ),
    routine(
        r#"FUNC dnum BitLShDnum(dnum Value, num ShiftSteps \num Size)"#,
        "Shifts an integer dnum left by 1-52 steps, within Size bits when given.",
    ),
    routine(
        r#"FUNC byte BitRSh(byte BitData, num ShiftSteps)"#,
        "Shifts a byte right by 1-8 steps; bits pushed out are lost.",
    ),
    routine(r#"FUNC dnum BitRShDnum(dnum Value, num ShiftSteps)"#, "Shifts an integer dnum right by 1-52 steps."),
    // --- Matrix instructions --------------------------------------------------------------
    // MatrixSolve, MatrixSolveQR and MatrixSVD: argument lists as in the RW6 manual extract
    // [S1] (`MatrixSolve A [\A_m] [\A_n] b x`, `MatrixSolveQR A [\A_m] [\A_n] Q R`,
    // `MatrixSVD A [\A_m] [\A_n] U S V [\Econ]`); the extract types every array as
    // `dnum{*}`; uncertain: read here as 2-D for the matrices (its text says m x n matrix).
    // The other six are not in the extract (RW 6.15) and follow the same pattern.
    // uncertain: added in RW 6.15.04; argument names, order and optional size arguments are a guess.
    routine(
        r#"PROC MatrixAdd(dnum A{*,*} \num A_m \num A_n, dnum B{*,*}, VAR dnum C{*,*})"#,
        "Adds two matrices element by element into C.",
    ),
    // uncertain: added in RW 6.15.04; argument names, order and optional size arguments are a guess.
    routine(
        r#"PROC MatrixSub(dnum A{*,*} \num A_m \num A_n, dnum B{*,*}, VAR dnum C{*,*})"#,
        "Subtracts matrix B from matrix A element by element into C.",
    ),
    // uncertain: added in RW 6.15.04; the matrix-or-scalar second operand form is a guess.
    routine(
        r#"PROC MatrixMult(dnum A{*,*} \num A_m \num A_n, dnum B{*,*} | dnum Scalar, VAR dnum C{*,*})"#,
        "Multiplies a matrix by another matrix or by a scalar into C.",
    ),
    // uncertain: added in RW 6.15.04; argument names and optional size arguments are a guess.
    routine(
        r#"PROC MatrixTranspose(dnum A{*,*} \num A_m \num A_n, VAR dnum AT{*,*})"#,
        "Writes the transpose of matrix A into AT.",
    ),
    // uncertain: added in RW 6.15.04; argument names and optional size argument are a guess.
    routine(
        r#"PROC MatrixInverse(dnum A{*,*} \num A_n, VAR dnum AInv{*,*})"#,
        "Writes the inverse of a square matrix A into AInv.",
    ),
    // uncertain: added in RW 6.15.04; argument names and optional size arguments are a guess.
    routine(r#"PROC MatrixReset(VAR dnum A{*,*} \num A_m \num A_n)"#, "Sets every element of a matrix to zero."),
    routine(
        r#"PROC MatrixSolve(dnum A{*,*} \num A_m \num A_n, dnum b{*}, VAR dnum x{*})"#,
        "Solves the linear system A*x = b (least squares when A has more rows).",
    ),
    routine(
        r#"PROC MatrixSolveQR(dnum A{*,*} \num A_m \num A_n, VAR dnum Q{*,*}, VAR dnum R{*,*})"#,
        "Computes a QR factorisation of matrix A into Q and R.",
    ),
    routine(
        r#"PROC MatrixSVD(dnum A{*,*} \num A_m \num A_n, VAR dnum U{*,*}, VAR dnum S{*}, VAR dnum V{*,*} \switch Econ)"#,
        "Computes a singular value decomposition of matrix A into U, S and V.",
    ),
    // --- Shape fitting --------------------------------------------------------------------
    // Arguments as in the RW6 manual extract [S1]. uncertain: Points read as an N x 3 dnum
    // matrix, one point per row (the extract only says an array of dnum).
    routine(
        r#"PROC FitCircle(dnum Points{*,*} \num NumPoints, VAR pos Center, VAR num Radius, VAR pos Normal \VAR num RMS \VAR num MaxErr \VAR num IndexWorst)"#,
        "Fits a circle to a set of 3D points; returns centre, radius and plane normal.",
    ),
];
