<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData>
  <DateTime time="12:00:00" date="2024-01-01"/>
  <User name="eulermap"/>
  <DataFileName name="cow.off"/>
  <templateName name=""/>
 </DocumentData>
 <point x="0.522196" y="0.167053" z="0.010733" active="1" name="nose"/>
 <point x="-0.510746" y="-0.125393" z="-0.004359" active="1" name="tail"/>
 <point x="0.13028" y="-0.314633" z="-0.091709" active="1" name="hoof_front_left"/>
 <point x="0.13028" y="-0.314633" z="0.091709" active="1" name="hoof_front_right"/>
 <point x="-0.369903" y="-0.319838" z="-0.105921" active="1" name="hoof_back_left"/>
 <point x="-0.369903" y="-0.319838" z="0.105921" active="1" name="hoof_back_right"/>
</PickedPoints>
