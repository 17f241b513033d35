//! The predefined errors the interpreter raises itself. Their numbers are the values
//! of the `ERR_*` constants in the catalogue, read when a program is loaded.

macro_rules! errors {
    ($( $variant:ident = $name:literal, )*) => {
        /// A predefined error the interpreter raises.
        #[derive(Debug, Clone, Copy, PartialEq, Eq)]
        pub enum Err { $( $variant, )* }

        impl Err {
            pub const ALL: &'static [Err] = &[ $( Err::$variant, )* ];

            pub fn name(self) -> &'static str {
                match self { $( Err::$variant => $name, )* }
            }
        }
    };
}

errors! {
    DivZero = "ERR_DIVZERO",
    OutOfBounds = "ERR_OUTOFBND",
    StringTooLong = "ERR_STRTOOLNG",
    NotPresent = "ERR_NOTPRES",
    FuncNoReturn = "ERR_FNCNORET",
    RefUnknownProc = "ERR_REFUNKPRC",
    CallProc = "ERR_CALLPROC",
    IllegalRaise = "ERR_ILLRAISE",
    TooManyRetries = "ERR_EXCRTYMAX",
    ExecPlaceholder = "ERR_EXECPHR",
    IntNotValue = "ERR_INT_NOTVAL",
    IntMaxValue = "ERR_INT_MAXVAL",
    SymAccess = "ERR_SYM_ACCESS",
    SymbolType = "ERR_SYMBOL_TYPE",
    TaskName = "ERR_TASKNAME",
    ArgValue = "ERR_ARGVALERR",
    NumLimit = "ERR_NUM_LIMIT",
    IllegalDim = "ERR_ILLDIM",
    Overflow = "ERR_OVERFLOW",
    WaitMaxTime = "ERR_WAIT_MAXTIME",
    TpNoClient = "ERR_TP_NO_CLIENT",
    TpMaxTime = "ERR_TP_MAXTIME",
    UiInitValue = "ERR_UI_INITVALUE",
    UiMaxMin = "ERR_UI_MAXMIN",
    UiNotInt = "ERR_UI_NOTINT",
}
