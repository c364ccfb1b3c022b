MODULE load_modules_order
  ! Modules unload in any order (EraseModule names a loaded module by its
  ! name): unloading one loaded before another that is still loaded keeps
  ! the later one.
  VAR iodev f;

  PROC main()
    write_part "a.mod", "PartA";
    write_part "b.mod", "PartB";
    Load "HOME:/a.mod";
    Load "HOME:/b.mod";
    EraseModule "PartB";
    TPWrite "b "\Bool:=ModExist("PartB");
    UnLoad "HOME:/a.mod";
    TPWrite "a "\Bool:=ModExist("PartA");
    Load "HOME:/a.mod";
    Load "HOME:/b.mod";
    UnLoad "HOME:/a.mod";
    TPWrite "a "\Bool:=ModExist("PartA");
    TPWrite "b "\Bool:=ModExist("PartB");
  ENDPROC

  PROC write_part(string file, string name)
    Open "HOME:" \File:=file, f \Write;
    Write f, "MODULE " + name;
    Write f, "ENDMODULE";
    Close f;
  ENDPROC
ENDMODULE
!> [Load at load_modules_order.mod:10] PartA from HOME:/a.mod
!> [Load at load_modules_order.mod:11] PartB from HOME:/b.mod
!> [EraseModule at load_modules_order.mod:12] PartB
!> b FALSE
!> [UnLoad at load_modules_order.mod:14] PartA
!> a FALSE
!> [Load at load_modules_order.mod:16] PartA from HOME:/a.mod
!> [Load at load_modules_order.mod:17] PartB from HOME:/b.mod
!> [UnLoad at load_modules_order.mod:18] PartA
!> a FALSE
!> b TRUE
