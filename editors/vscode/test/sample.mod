! SYNTAX TEST "source.rapid" "RAPID module"
MODULE MainModule (SYSMODULE)
! <------ storage.type.module.rapid
!      ^^^^^^^^^^ entity.name.type.module.rapid
!                  ^^^^^^^^^ storage.modifier.rapid
  RECORD part
! ^^^^^^ storage.type.record.rapid
!        ^^^^ entity.name.type.record.rapid
    num id;
!   ^^^ support.type.rapid
  ENDRECORD
  LOCAL PERS num total := 0.5E2;
! ^^^^^ storage.modifier.rapid
!       ^^^^ storage.type.data.rapid
!                      ^^ keyword.operator.assignment.rapid
!                         ^^^^^ constant.numeric.rapid
  VAR string name := "say ""hi""";
!                    ^ string.quoted.double.rapid
!                         ^^ constant.character.escape.rapid
!                                ^ - string.quoted.double.rapid
  PROC main()
! ^^^^ storage.type.function.rapid
!      ^^^^ entity.name.function.rapid
    IF total > 10 AND NOT FALSE THEN
!   ^^ keyword.control.rapid
!            ^ keyword.operator.comparison.rapid
!                 ^^^ keyword.operator.logical.rapid
!                         ^^^^^ constant.language.boolean.rapid
      TPWrite "total " \Num:=total; ! a comment
!                      ^^^^ variable.parameter.optional.rapid
!                                   ^^^^^^^^^^^ comment.line.exclamation.rapid
    ENDIF
!   ^^^^^ keyword.control.rapid
    <SMT>
!   ^^^^^ invalid.illegal.placeholder.rapid
  ENDPROC
! ^^^^^^^ storage.type.rapid
  FUNC num twice(num x)
! ^^^^ storage.type.function.rapid
!      ^^^ support.type.rapid
!          ^^^^^ entity.name.function.rapid
    RETURN x * 2 + 0x1F DIV 2;
!   ^^^^^^ keyword.control.rapid
!                  ^^^^ constant.numeric.integer.rapid
!                       ^^^ keyword.operator.arithmetic.rapid
  ENDFUNC
ENDMODULE
! <--------- storage.type.rapid
