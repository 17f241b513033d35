! expect: E0102 line 3
! a module name longer than 32 characters
MODULE module_name_that_is_far_too_long_x
  VAR num n;
ENDMODULE
