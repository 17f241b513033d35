//! How the controller turns values into text (TPWrite, NumToStr, ValToStr, Write).
