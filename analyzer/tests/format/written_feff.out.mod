! as written: a U+FEFF between tokens is kept with the blanks around it
MODULE Feff
    PROC main()
        x:=1;﻿y:=2;
﻿    MoveL p10,﻿v1000,z50,tool0;
    ENDPROC
ENDMODULE
