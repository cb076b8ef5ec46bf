(Run the three dialog-driven cycles like an operator at the User buttons:)
(  ecnc run --ini examples/lathe/cnc.ini examples/lathe/dialogs.nc)
(      --answer ok --answer ok:#1423=48,#1425=-30 --answer ok:#1451=16,#1452=2)
G18 G21 G90
gosub home_all
gosub user_1
gosub user_2
gosub user_3
G28
M30
