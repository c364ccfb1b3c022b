MODULE sockets_wait_max_empty_network
  ! A server waiting with WAIT_MAX where nobody is on the simulated
  ! network waits forever: the run ends as a wait nothing can end, not
  ! when the time budget runs out.
  VAR socketdev server;
  VAR socketdev peer;
  PROC main()
    SocketCreate server;
    SocketBind server, "192.168.125.1", 1025;
    SocketListen server;
    TPWrite "listening";
    SocketAccept server, peer \Time:=WAIT_MAX;
    TPWrite "never";
  ENDPROC
ENDMODULE
!> listening
!! deadlock at 12
