//! rapid-lib: the one catalogue of RAPID's predefined types, data, instructions and
//! functions. The checker, the VM, the formatter and the language server all read it.

pub mod catalogue;
