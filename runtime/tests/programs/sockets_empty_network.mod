MODULE sockets_empty_network
  ! Sockets on a network where nobody answers: a connect and an accept
  ! wait their whole \Time (simulated) and time out; a receive on a socket
  ! that is not connected fails as closed; the states SocketGetStatus
  ! gives.
  VAR socketdev client;
  VAR socketdev server;
  VAR socketdev peer;
  VAR string text;
  VAR clock clk;

  PROC main()
    ClkStart clk;
    TPWrite "not created "\Bool:=SocketGetStatus(client) = SOCKET_CLOSED;
    SocketCreate client;
    TPWrite "created "\Bool:=SocketGetStatus(client) = SOCKET_CREATED;
    try_connect;
    TPWrite "after "\Num:=ClkRead(clk);
    SocketCreate server;
    SocketBind server, "192.168.125.1", 1025;
    TPWrite "bound "\Bool:=SocketGetStatus(server) = SOCKET_BOUND;
    SocketListen server;
    TPWrite "listening "\Bool:=SocketGetStatus(server) = SOCKET_LISTENING;
    SocketAccept server, peer \Time:=10;
  ERROR
    TPWrite "accept timed out "\Bool:=ERRNO = ERR_SOCK_TIMEOUT;
    TPWrite "after "\Num:=ClkRead(clk);
    SocketReceive client \Str:=text;
  ENDPROC

  PROC try_connect()
    SocketConnect client, "192.168.125.10", 1025 \Time:=5;
  ERROR
    TPWrite "connect timed out "\Bool:=ERRNO = ERR_SOCK_TIMEOUT;
    TRYNEXT;
  ENDPROC
ENDMODULE
!> not created TRUE
!> created TRUE
!> connect timed out TRUE
!> after 5
!> bound TRUE
!> listening TRUE
!> accept timed out TRUE
!> after 15
!! ERR_SOCK_CLOSED at 28
