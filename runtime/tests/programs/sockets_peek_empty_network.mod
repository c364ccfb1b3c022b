MODULE sockets_peek_empty_network
  ! SocketPeek on a network where nobody answers: a bound UDP socket has
  ! nothing waiting; a socket that is not connected fails as closed, at
  ! once (SocketPeek never waits).
  VAR socketdev udp;
  VAR socketdev tcp;
  VAR clock clk;

  PROC main()
    SocketCreate udp \UDP;
    SocketBind udp, "192.168.125.1", 6510;
    TPWrite "waiting "\Num:=SocketPeek(udp);
    SocketCreate tcp;
    ClkStart clk;
    TPWrite "tcp "\Num:=SocketPeek(tcp);
  ERROR
    TPWrite "closed "\Bool:=ERRNO = ERR_SOCK_CLOSED;
    TPWrite "after "\Num:=ClkRead(clk);
  ENDPROC
ENDMODULE
!> waiting 0
!> closed TRUE
!> after 0
