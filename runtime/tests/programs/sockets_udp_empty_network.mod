MODULE sockets_udp_empty_network
  ! UDP on a network where nobody answers: a datagram is sent (nobody hears
  ! it), none comes within \Time (simulated), and a UDP socket does not
  ! connect.
  VAR socketdev udp;
  VAR string msg;
  VAR string peer;
  VAR num port;
  VAR clock clk;

  PROC main()
    SocketCreate udp \UDP;
    TPWrite "created "\Bool:=SocketGetStatus(udp) = SOCKET_CREATED;
    SocketSendTo udp, "192.168.125.10", 6511 \Str:="hello";
    TPWrite "sent";
    SocketBind udp, "192.168.125.1", 6510;
    TPWrite "bound "\Bool:=SocketGetStatus(udp) = SOCKET_BOUND;
    ClkStart clk;
    SocketReceiveFrom udp \Str:=msg, peer, port \Time:=3;
  ERROR
    TPWrite "timed out "\Bool:=ERRNO = ERR_SOCK_TIMEOUT;
    TPWrite "after "\Num:=ClkRead(clk);
    SocketConnect udp, "192.168.125.10", 6511;
  ENDPROC
ENDMODULE
!> created TRUE
!> sent
!> bound TRUE
!> timed out TRUE
!> after 3
!! ERR_SOCK_CLOSED at 23
