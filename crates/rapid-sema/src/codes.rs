//! The one table of diagnostic codes. Codes are stable: never reuse or renumber one.
//!
//! `E…` codes are errors, `W…` codes are warnings. The first two digits group them:
//! 01 lexical and syntax, 02 names and scopes, 03 types and expressions, 04 routine
//! calls, 05 declarations, 06 flow and handlers, 07 system configuration.

macro_rules! diagnostic_codes {
    ($( $code:literal $severity:ident $name:ident : $summary:literal ; )*) => {
        /// A stable diagnostic code.
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
        pub enum Code { $( $name, )* }

        impl Code {
            /// Every code, in table order.
            pub const ALL: &'static [Code] = &[ $( Code::$name, )* ];

            /// The code as users see it, e.g. `E0201`.
            pub fn as_str(self) -> &'static str {
                match self { $( Code::$name => $code, )* }
            }

            /// Whether the code is an error or a warning.
            pub fn severity(self) -> Severity {
                match self { $( Code::$name => Severity::$severity, )* }
            }

            /// One line saying what the code is about (for `docs/diagnostics.md`).
            pub fn summary(self) -> &'static str {
                match self { $( Code::$name => $summary, )* }
            }

            /// The code's name, e.g. `UndefinedData`.
            pub fn name(self) -> &'static str {
                match self { $( Code::$name => stringify!($name), )* }
            }
        }
    };
}

/// How serious a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    Warning,
    Error,
}

#[rustfmt::skip]
diagnostic_codes! {
    // Lexical and syntax (reported by rapid-syntax, coded here).
    "E0101" Error   InvalidCharacter:          "a character that cannot start any RAPID token";
    "E0102" Error   IdentifierTooLong:         "an identifier longer than 32 characters";
    "E0103" Error   StringTooLong:             "a string literal longer than 80 characters";
    "E0104" Error   UnterminatedString:        "a string literal without its closing quote on the same line";
    "E0105" Error   InvalidStringEscape:       "a backslash in a string not followed by a backslash or two hex digits";
    "E0106" Error   MalformedNumber:           "a number literal that does not follow the num literal grammar";
    "E0107" Error   NumberOutOfRange:          "a number literal outside the range of IEEE 754 numbers";
    "E0108" Error   NonLatin1Character:        "a character outside ISO 8859-1 (Latin-1) in a string literal";
    "E0109" Error   EncryptedModule:           "an ABB-encrypted module, which cannot be read";
    "E0110" Error   UnterminatedHeader:        "a %%% file header without its closing %%%";
    "E0111" Error   TooManyErrors:             "so many errors that the file is probably not RAPID; reporting stopped";
    "W0112" Warning TooManyWarnings:           "so many warnings (and no error) in a file that reporting stopped";
    "E0120" Error   UnexpectedToken:           "a token the grammar does not allow here";
    "E0121" Error   UnclosedBlock:             "a MODULE, routine, RECORD, IF, FOR, WHILE or TEST without its END keyword";
    "E0122" Error   NestingTooDeep:            "expressions or statements nested too deeply to process";
    "E0123" Error   ModuleAttributeOrder:      "module attributes out of the manual's order or in a forbidden combination";
    "E0124" Error   DuplicateModuleAttribute:  "a module attribute given twice";
    "E0125" Error   CompoundInCompactIf:       "a compact IF whose statement is not a simple statement";
    "E0126" Error   ReservedWordAsName:        "a reserved word used where a name is expected";
    "E0127" Error   TooManyDimensions:         "an array with more than 3 dimensions";
    "E0128" Error   OutsideModule:             "text outside MODULE ... ENDMODULE";
    "W0131" Warning EncryptedModuleOpaque:     "an ABB-encrypted module of a task, loaded unread: the names it defines are unknown";
    "E0130" Error   ProgramFileEntry:          "a .pgf program file entry that names no readable module";

    // Names and scopes.
    "E0201" Error   UndefinedData:             "a name that is not declared data in scope";
    "W0202" Warning UndefinedProcedure:        "a call to a procedure defined nowhere in the task (ERR_REFUNKPRC at run time)";
    "W0203" Warning UndefinedFunction:         "a call to a function defined nowhere in the task (ERR_REFUNKFUN at run time)";
    "E0204" Error   UndefinedType:             "a data type that is not defined";
    "E0205" Error   DuplicateDeclaration:      "two declarations of one name where the scope rules forbid it";
    "E0206" Error   UndefinedLabel:            "a GOTO to a label that the routine does not have";
    "E0207" Error   DuplicateLabel:            "two labels of one name, or a label named like routine data";
    "E0208" Error   AmbiguousGlobal:           "one global name declared in two modules of the task";
    "E0209" Error   NotAProcedure:             "a procedure call whose name is not a procedure";
    "E0210" Error   NotAFunction:              "a function call whose name is not a function";
    "E0211" Error   NotAType:                  "a type position whose name is not a data type";
    "E0212" Error   NotData:                   "a data reference whose name is a routine or type";
    "E0213" Error   GotoIntoBlock:             "a GOTO into an IF, FOR, WHILE or TEST body from outside it";
    "E0214" Error   NotATrap:                  "CONNECT ... WITH a name that is not a TRAP routine";
    "E0215" Error   TrapCalled:                "a TRAP routine called like a procedure";
    "E0216" Error   DuplicateModule:           "two modules of one name in the task";
    "E0217" Error   OptionMissing:             "a name of a software option (Arc, EGM, ...) that this system does not have";
    "W0218" Warning UndefinedBesideEncrypted:  "a name defined nowhere readable in a task that loads an encrypted module, which may define it";

    // Types and expressions.
    "E0301" Error   TypeMismatch:              "a value of one type where another type is required";
    "E0302" Error   OperatorTypes:             "an operator applied to operand types it is not defined for";
    "E0303" Error   AggregateWithoutType:      "an aggregate where the context gives it no type";
    "E0304" Error   AggregateShape:            "an aggregate with the wrong number of components or elements";
    "E0305" Error   UnknownComponent:          "a record component the record type does not have";
    "E0306" Error   BadIndex:                  "indexing data that is not an array, or with the wrong number of indices";
    "E0307" Error   NonValueUse:               "a non-value type used in a value operation";
    "E0308" Error   SemiValueWrite:            "a semi-value (signal) data object initialised or assigned";
    "E0309" Error   ReadOnlyWrite:             "a write to a constant, a FOR loop variable or a read-only system variable";
    "E0310" Error   ConditionNotBool:          "a condition that is not a bool";
    "E0312" Error   BadArrayDimension:         "an array dimension that is not a positive integer constant";
    "E0313" Error   ArrayTooLarge:             "an array with more elements than the limit every array shares";
    "E0314" Error   NumLiteralRange:           "a num literal outside the single-precision range of num";

    // Routine calls.
    "E0401" Error   TooManyArguments:          "more required arguments than the routine has parameters";
    "E0402" Error   MissingArgument:           "a required argument left out";
    "E0403" Error   UnknownArgument:           "an argument name the routine has no parameter for";
    "E0404" Error   DuplicateArgument:         "an argument given twice, or two of a mutually exclusive group";
    "E0405" Error   SwitchWithValue:           "a value given to a switch argument";
    "E0406" Error   MissingArgumentValue:      "an optional argument without a value for a parameter that is not a switch";
    "E0407" Error   ConditionalFromRequired:   "a conditional argument \\x?y where y is not an optional parameter";
    "E0408" Error   ArgumentNotReference:      "an expression where the parameter needs a variable or a persistent";
    "E0409" Error   ArrayArgumentMismatch:     "an array argument whose rank differs from the parameter, or a scalar for an array";
    "E0410" Error   LateBindingNotString:      "a late-bound call % expr % whose expression is not a string";
    "E0411" Error   ArgumentOrder:             "arguments not in the order of the routine's parameters";
    "E0412" Error   RequiredAsOptional:        "a required parameter passed with \\ or an optional one without it";

    // Declarations.
    "E0501" Error   ConstInitNotConstant:      "a CONST or routine VAR initialiser that is not a constant expression";
    "E0502" Error   PersInitNotLiteral:        "a PERS initialiser that is not a literal expression";
    "E0503" Error   PersInitMissing:           "a LOCAL or TASK PERS without an initial value";
    "E0504" Error   ConstInitMissing:          "a CONST without a value";
    "E0505" Error   PersInRoutine:             "a PERS declared inside a routine";
    "E0506" Error   LocalInRoutine:            "LOCAL or TASK used on a declaration inside a routine";
    "E0507" Error   NonValueDeclaration:       "a non-value type declared CONST or PERS, or given an initial value";
    "E0508" Error   FuncReturnsNonValue:       "a FUNC whose return type is not a value type";
    "E0509" Error   RecursiveRecord:           "a RECORD that contains itself";
    "E0510" Error   AliasOfAlias:              "an ALIAS defined upon another alias type";
    "E0511" Error   SwitchNotOptional:         "a switch parameter that is not optional, or an array of switch";
    "E0513" Error   RequiredAlternatives:      "alternatives ( | ) between parameters that are not optional";

    // Flow control and handlers.
    "E0601" Error   RetryOutsideErrorHandler:  "RETRY or TRYNEXT outside an ERROR handler";
    "E0602" Error   ReturnValueMismatch:       "RETURN with a value in a PROC or TRAP, or without one in a FUNC";
    "W0603" Warning FuncWithoutReturn:         "a FUNC with no RETURN statement (ERR_FNCNORET at run time)";
    "E0604" Error   BackwardOutsideProc:       "a BACKWARD handler in a FUNC or TRAP";
    "W0605" Warning IgnoredInUndo:             "Stop, Break, RAISE or RETURN in an UNDO handler, which ignores them";
    "E0606" Error   MotionInUndo:              "a motion instruction in an UNDO handler";
    "W0607" Warning RaiseNumberRange:          "RAISE with a constant number outside 1..90 (ERR_ILLRAISE at run time)";
    "E0608" Error   RaiseWithoutNumber:        "RAISE without an error number outside an ERROR handler";
    "E0609" Error   ConnectTargetNotVariable:  "CONNECT to something that is not an intnum variable";
    "E0610" Error   BadHandlerErrorNumber:     "an ERROR handler number list entry that is not an errnum constant";

    // System configuration (a backup's SYSPAR/*.cfg, a manifest; read by rapid-cli) and the
    // system of tasks as a whole.
    "E0701" Error   ConfigFile:                "a line of a .cfg configuration file that cannot be read, or a configuration the controller refuses";
    "W0702" Warning ConfigNotSimulated:        "a configuration setting RobotWare accepts that `rapid run` does not simulate or interpret (a system input action or output status, a line of a domain not interpreted, a task naming itself as its foreground task)";
    "E0703" Error   SharedPersMismatch:        "a global PERS declared with another type or array size than in another task of the system (one persistent for all tasks, §1.20)";
    "E0704" Error   EventRoutineMissing:       "an event routine (SYS.cfg CAB_EXEC_HOOKS) that is not a procedure of a task it is configured for";
    "E0705" Error   EntryRoutineMissing:       "a configured task whose entry routine (SYS.cfg -Entry, a manifest's entry; main by default) is not a global procedure of the task (the first task's unless `rapid run --entry` gives another)";
    "W0706" Warning ProgramMemoryFull:         "a task's program with more source text than program memory holds (64 MiB, our figure: ABB's is not public); a controller may refuse to load it";
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_unique_and_well_formed() {
        let mut seen = rustc_hash::FxHashSet::default();
        for code in Code::ALL {
            let text = code.as_str();
            assert!(seen.insert(text), "duplicate code {text}");
            assert_eq!(text.len(), 5);
            let prefix = if code.severity() == Severity::Error { 'E' } else { 'W' };
            assert!(text.starts_with(prefix), "{text} severity prefix");
        }
    }
}
