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
    RefUnknownFunc = "ERR_REFUNKFUN",
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
    // Files, directories and character/binary I/O (§1.10, §1.16).
    FileAccess = "ERR_FILEACC",
    FileExists = "ERR_FILEEXIST",
    FileOpen = "ERR_FILEOPEN",
    FileSize = "ERR_FILESIZE",
    FileNotFound = "ERR_FILNOTFND",
    AnyBinCheck = "ERR_RANYBIN_CHK",
    AnyBinEof = "ERR_RANYBIN_EOF",
    ReceiveData = "ERR_RCVDATA",
    DeviceMaxTime = "ERR_DEV_MAXTIME",
    NameInvalid = "ERR_NAME_INVALID",
    ModuleNotLoaded = "ERR_MOD_NOTLOADED",
    // Sockets (§1.10).
    SockAddrInUse = "ERR_SOCK_ADDR_INUSE",
    SockAddrInvalid = "ERR_SOCK_ADDR_INVALID",
    SockClosed = "ERR_SOCK_CLOSED",
    SockIsBound = "ERR_SOCK_IS_BOUND",
    SockIsConn = "ERR_SOCK_IS_CONN",
    SockNetUnreach = "ERR_SOCK_NET_UNREACH",
    SockNotBound = "ERR_SOCK_NOT_BOUND",
    SockNotConn = "ERR_SOCK_NOT_CONN",
    SockTimeout = "ERR_SOCK_TIMEOUT",
    SockUnspec = "ERR_SOCK_UNSPEC",
    // Math and system support (§1.15, §1.17).
    CalcDivZero = "ERR_CALC_DIVZERO",
    CalcNeg = "ERR_CALC_NEG",
    CalcOverflow = "ERR_CALC_OVERFLOW",
    NotEqualDim = "ERR_NOTEQDIM",
    InvalidDim = "ERR_INVDIM",
    ArraySize = "ERR_ARRAY_SIZE",
    TextNotExist = "ERR_TXTNOEXIST",
    NotArray = "ERR_NOTARR",
    ArgName = "ERR_ARGNAME",
    // Loading, unloading and saving program modules (§1.17).
    LinkRef = "ERR_LINKREF",
    Loaded = "ERR_LOADED",
    Unload = "ERR_UNLOAD",
    Module = "ERR_MODULE",
    Syntax = "ERR_SYNTAX",
    IoError = "ERR_IOERROR",
    PrgMemFull = "ERR_PRGMEMFULL",
    NotSaved = "ERR_NOTSAVED",
    LoadNoInUse = "ERR_LOADNO_INUSE",
    LoadNoNoUse = "ERR_LOADNO_NOUSE",
    UnknownLoad = "ERR_UNKPROC",
    // I/O signals (§1.9).
    NoAliasIoDef = "ERR_NO_ALIASIO_DEF",
    AliasIoDef = "ERR_ALIASIO_DEF",
    AliasIoType = "ERR_ALIASIO_TYPE",
    AoLim = "ERR_AO_LIM",
    GoLim = "ERR_GO_LIM",
    SigNotValid = "ERR_SIG_NOT_VALID",
    // Interrupts (§1.11).
    UnknownInterrupt = "ERR_UNKINO",
    AlreadyConnected = "ERR_ALRDYCNT",
    // Configuration data (§1.17).
    CfgIllType = "ERR_CFG_ILLTYPE",
    CfgIllDomain = "ERR_CFG_ILL_DOMAIN",
    CfgLimit = "ERR_CFG_LIMIT",
    CfgNotFound = "ERR_CFG_NOTFND",
    CfgOutOfBounds = "ERR_CFG_OUTOFBOUNDS",
    CfgWriteFile = "ERR_CFG_WRITEFILE",
    // Multitasking (§1.20).
    WaitSyncTask = "ERR_WAITSYNCTASK",
    // RAPID Message Queue (§1.10).
    RmqDim = "ERR_RMQ_DIM",
    RmqFull = "ERR_RMQ_FULL",
    RmqInvalid = "ERR_RMQ_INVALID",
    RmqInvalidMsg = "ERR_RMQ_INVMSG",
    RmqMsgSize = "ERR_RMQ_MSGSIZE",
    RmqName = "ERR_RMQ_NAME",
    RmqNoMsg = "ERR_RMQ_NOMSG",
    RmqTimeout = "ERR_RMQ_TIMEOUT",
    RmqValue = "ERR_RMQ_VALUE",
    // Motion settings and position functions (§1.7, §1.8).
    SpeedRefreshLim = "ERR_SPEED_REFRESH_LIM",
    Frame = "ERR_FRAME",
    OutsideReach = "ERR_OUTSIDE_REACH",
    RobLimit = "ERR_ROBLIMIT",
    WhlSearch = "ERR_WHLSEARCH",
    SigSupSearch = "ERR_SIGSUPSEARCH",
    CnvNotActive = "ERR_CNV_NOT_ACT",
    CnvConnect = "ERR_CNV_CONNECT",
    // I/O devices and networks (§1.9).
    NoRunUnit = "ERR_NORUNUNIT",
    IoEnable = "ERR_IOENABLE",
    AxisPar = "ERR_AXIS_PAR",
    AxisInd = "ERR_AXIS_IND",
    SpeedLimValue = "ERR_SPEEDLIM_VALUE",
    // Path stop and restart (§2.2.6).
    AlreadyMoving = "ERR_ALRDY_MOVING",
    PathDist = "ERR_PATHDIST",
    ConcMax = "ERR_CONC_MAX",
    BwdLimit = "ERR_BWDLIMIT",
    // Triggers (TriggLIOs/TriggJIOs name their signals).
    SigName = "ERR_SIG_NAME",
    // Synchronized movement (MultiMove).
    SyncMoveOn = "ERR_SYNCMOVEON",
    SyncMoveOff = "ERR_SYNCMOVEOFF",
    WobjMoving = "ERR_WOBJ_MOVING",
}
